#include "export/exchange_text.h"

#include <charconv>
#include <cmath>
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

std::string utc_time_stamp(const char* strftime_format) {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buf[64];
  const std::size_t n = std::strftime(buf, sizeof buf, strftime_format, &utc);
  return std::string(buf, n);
}

}  // namespace polarform
