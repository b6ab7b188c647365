// One direction of a fitted single-valued B-spline function F: its degree and knots, clamped
// (Bae 2002, eq. (3.4)) or periodic (eq. (3.9), whose last `degree` coefficients repeat the first,
// eq. (3.10)). The fitters build the tensor-product space of F from two axes (a curve is a 1 x n
// surface whose u axis has degree 0).
#pragma once

#include <vector>

#include "src/nurbs/knots.h"

namespace polarform {

struct SplineAxis {
  int degree = 0;
  Knots knots;            // clamped, or periodic_knots(degree, breaks)
  bool periodic = false;

  // Basis functions on the knots (the coefficient count before the periodic identification).
  int size() const { return static_cast<int>(knots.size()) - degree - 1; }
  // Independent coefficients: size() - degree when periodic (Bae 2002, eq. (3.10)).
  int distinct() const { return periodic ? size() - degree : size(); }
  double front() const { return knots[degree]; }
  double back() const { return knots[size()]; }
  // The breakpoints b_0 = front < ... < b_k = back.
  std::vector<double> breaks() const;
};

// Clamped axis of `degree` on the breakpoints (simple interior knots); breaks.size() >= 2.
SplineAxis clamped_axis(int degree, const std::vector<double>& breaks);

// Periodic axis on the breakpoints (Bae 2002, eq. (3.9)); needs at least degree + 1 spans so that
// the identification (3.10) leaves each coefficient one basis function per period.
SplineAxis periodic_axis(int degree, const std::vector<double>& breaks);

}  // namespace polarform
