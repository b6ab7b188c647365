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

namespace {

// The base letters of U+00C0..U+017F ('_' where there is none; "AE", "ss", … below).
constexpr std::string_view kLatinBase =
    "AAAAAAACEEEEIIIIDNOOOOO_OUUUUYT_aaaaaaaceeeeiiiidnooooo_ouuuuyty"  // U+00C0..U+00FF
    "AaAaAaCcCcCcCcDdDdEeEeEeEeEeGgGgGgGgHhHhIiIiIiIiIiJjJjKkkLlLlLlLlLl"
    "NnNnNnnNnOoOoOoOoRrRrRrSsSsSsSsTtTtTtUuUuUuUuUuUuWwYyYZzZzZzs";  // U+0100..U+017F

// The letters that fold to two: Æ æ ß Þ þ Ĳ ĳ Œ œ.
std::string_view two_letters(char32_t c) {
  switch (c) {
    case U'\u00C6':
      return "AE";
    case U'\u00E6':
      return "ae";
    case U'\u00DF':
      return "ss";
    case U'\u00DE':
      return "Th";
    case U'\u00FE':
      return "th";
    case U'\u0132':
      return "IJ";
    case U'\u0133':
      return "ij";
    case U'\u0152':
      return "OE";
    case U'\u0153':
      return "oe";
    default:
      return {};
  }
}

}  // namespace

std::string ascii_text(std::string_view utf8) {
  std::string out;
  for (std::size_t i = 0; i < utf8.size();) {
    const unsigned char c = utf8[i];
    if (c >= 0x20 && c < 0x7F) {
      out += static_cast<char>(c);
      ++i;
      continue;
    }
    // A 2-byte UTF-8 sequence covers U+0080..U+07FF, Latin-1 and Latin Extended-A among them.
    const bool two = (c & 0xE0) == 0xC0 && i + 1 < utf8.size() &&
                     (static_cast<unsigned char>(utf8[i + 1]) & 0xC0) == 0x80;
    const char32_t code =
        two ? ((c & 0x1F) << 6) | (static_cast<unsigned char>(utf8[i + 1]) & 0x3F) : 0;
    if (two && !two_letters(code).empty()) {
      out += two_letters(code);
    } else if (two && code >= 0xC0 && code <= 0x17F) {
      out += kLatinBase[code - 0xC0];
    } else {
      out += '_';
    }
    // Skip the rest of the character: continuation bytes.
    ++i;
    while (i < utf8.size() && (static_cast<unsigned char>(utf8[i]) & 0xC0) == 0x80) ++i;
  }
  return out;
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
