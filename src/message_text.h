// Numbers in messages: polarform works in radians and mm, users read degrees and short numbers. One
// formatting rule for every diagnostic and error of polarform ("127.5°", "0.25").
#pragma once

#include <string>

namespace polarform {

// The angle in degrees with up to 6 significant digits and a degree sign.
std::string degrees_text(double radians);
// A number with up to 6 significant digits, classic locale.
std::string number_text(double value);

}  // namespace polarform
