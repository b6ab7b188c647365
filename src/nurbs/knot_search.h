// Binary-search multiplicity for the kernel's hot loops: knot vectors are validated non-decreasing,
// so the copies of a value form one run that equal_range finds in O(log n) (knots.h's
// multiplicity() counts the whole vector).
#pragma once

#include <algorithm>

#include "src/nurbs/knots.h"

namespace polarform {

inline int sorted_multiplicity(const Knots& knots, double u) {
  const auto [lo, hi] = std::equal_range(knots.begin(), knots.end(), u);
  return static_cast<int>(hi - lo);
}

}  // namespace polarform
