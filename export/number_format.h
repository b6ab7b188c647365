// Locale-independent number text for the writers: the shortest decimal that reads back exactly
// (CSV data) and fixed-precision decimals (SVG coordinates, tick labels). Everything goes through
// std::to_chars, so the global C++ or C locale never changes the output.
#pragma once

#include <string>

namespace polarform {

// Shortest text that strtod reads back to exactly v; "nan", "inf" or "-inf" if v is not finite.
std::string format_round_trip(double v);

// v rounded to exactly `decimals` (0..20) digits after the point; a zero result carries no '-'.
std::string format_fixed(double v, int decimals);

// Like format_fixed without trailing zeros or a trailing point: 12.50 -> "12.5", 3.00 -> "3".
std::string format_trimmed(double v, int decimals);

}  // namespace polarform
