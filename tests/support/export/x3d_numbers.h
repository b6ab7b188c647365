// Reading an X3D attribute back: the numbers of an MFFloat / MFVec3f / MFInt32 value, in order,
// commas taken as separators (the classic locale, whatever the global one).
#pragma once

#include <locale>
#include <sstream>
#include <string>
#include <vector>

namespace polarform::exchange_test {

inline std::vector<double> x3d_numbers(const char* text) {
  std::string s = text ? text : "";
  for (char& c : s)
    if (c == ',') c = ' ';
  std::istringstream in(s);
  in.imbue(std::locale::classic());
  std::vector<double> out;
  for (double x; in >> x;) out.push_back(x);
  return out;
}

}  // namespace polarform::exchange_test
