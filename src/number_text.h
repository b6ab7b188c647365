// Numbers as text, one rule for all of polarform, never touched by the global C or C++ locale:
// messages and diagnostics read short numbers ("127.5°", "0.25": 6 significant digits), data files
// read the shortest decimal that reads back exactly (CSV, JSON), drawings read fixed decimals (SVG
// coordinates, tick labels, report tables).
#pragma once

#include <string>

namespace polarform {

// A number with up to 6 significant digits: the form of every number in a message.
std::string number_text(double value);
// The angle in degrees with up to 6 significant digits and a degree sign.
std::string degrees_text(double radians);

// Shortest text that strtod reads back to exactly v; "nan", "inf" or "-inf" if v is not finite.
std::string format_round_trip(double v);

// v rounded to exactly `decimals` (0..20) digits after the point; a zero result carries no '-'.
std::string format_fixed(double v, int decimals);

// Like format_fixed without trailing zeros or a trailing point: 12.50 -> "12.5", 3.00 -> "3".
std::string format_trimmed(double v, int decimals);

}  // namespace polarform
