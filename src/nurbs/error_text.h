// Number formatting for the kernel's error messages: enough digits that two values differing in
// their last places (a mismatched domain end, a knot just outside the domain) read differently.
#pragma once

#include <cstdio>
#include <string>

namespace polarform {

inline std::string to_text(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.16g", x);
  return buf;
}

}  // namespace polarform
