#include "export/exchange_text.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>

#include "src/error.h"

namespace polarform {

std::string exchange_real(double x, char exponent_letter) {
  if (!std::isfinite(x)) throw InputError("exchange file: cannot write a non-finite real");
  if (x == 0.0) return "0.0";
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, x);  // shortest round trip
  if (ec != std::errc()) throw InputError("exchange file: cannot format a real");
  const std::string text(buf, end);
  const std::size_t e = text.find('e');
  std::string mantissa = text.substr(0, e);
  if (mantissa.find('.') == std::string::npos) mantissa += ".0";
  if (e == std::string::npos) return mantissa;
  return mantissa + exponent_letter + text.substr(e + 1);
}

std::time_t stamp_time() {
  const char* epoch = std::getenv("SOURCE_DATE_EPOCH");
  if (!epoch) return std::time(nullptr);
  long long seconds = 0;
  const char* end = epoch + std::strlen(epoch);
  const auto [ptr, ec] = std::from_chars(epoch, end, seconds);
  if (ec != std::errc() || ptr != end || *epoch == '\0' || seconds < 0)
    throw InputError(
        "SOURCE_DATE_EPOCH: expected the seconds since 1970-01-01 UTC as a "
        "non-negative integer, got \"" +
        std::string(epoch) + "\"");
  return static_cast<std::time_t>(seconds);
}

std::string utc_time_stamp(const char* strftime_format) {
  const std::time_t now = stamp_time();
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buf[64];
  const std::size_t n = std::strftime(buf, sizeof buf, strftime_format, &utc);
  return std::string(buf, n);
}

}  // namespace polarform
