#include "src/number_text.h"

#include <array>
#include <charconv>
#include <cmath>
#include <locale>
#include <sstream>

#include "src/units.h"

namespace polarform {

namespace {

std::string non_finite(double v) {
  if (std::isnan(v)) return "nan";
  return v > 0 ? "inf" : "-inf";
}

}  // namespace

std::string number_text(double value) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.precision(6);
  out << value;
  return out.str();
}

std::string degrees_text(double radians) { return number_text(radians * kDegreesPerRadian) + "°"; }

std::string format_round_trip(double v) {
  if (!std::isfinite(v)) return non_finite(v);
  std::array<char, 32> buf;
  const auto result = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  return std::string(buf.data(), result.ptr);
}

std::string format_fixed(double v, int decimals) {
  if (!std::isfinite(v)) return non_finite(v);
  // 309 integer digits for DBL_MAX, a sign, a point and up to 20 decimals.
  std::array<char, 340> buf;
  const auto result =
      std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::fixed, decimals);
  std::string text(buf.data(), result.ptr);
  if (text.front() == '-' && text.find_first_not_of("0.", 1) == std::string::npos) text.erase(0, 1);
  return text;
}

std::string format_trimmed(double v, int decimals) {
  std::string text = format_fixed(v, decimals);
  if (text.find('.') != std::string::npos) {
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
  }
  return text;
}

}  // namespace polarform
