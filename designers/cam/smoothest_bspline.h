// The B-spline cam segment: a B-spline of chosen degree and number of control values on uniform
// clamped knots whose endpoint values and derivatives are linear equality constraints and whose
// remaining freedom minimises ∫ (f^(r))² du over the segment (r = 2: least bending, r = 3: least
// jerk). Angeles 1983 / MacCarthy 1988 (quintic splines for kinematic design), solved with the
// constrained least squares of Bae 2002, Appendix C.
#pragma once

#include <span>

#include "src/nurbs/bspline.h"

namespace polarform {

// The most control values a B-spline law may have: its dense constrained least squares stays well
// under a second and a few MB (input limit, checked before any allocation).
constexpr int kMaxBSplineControlValues = 500;

struct BSplineLawSettings {
  int degree = 5;
  int control_values = 10;
  int minimised_derivative = 3;  // r in ∫ (f^(r))² du; 1 <= r <= degree

  bool operator==(const BSplineLawSettings&) const = default;
};

// f^(i)(u0) = start[i], f^(i)(u1) = end[i] for i = 0..k (k = start.size() - 1 <= 3), derivatives
// with respect to u. Throws InputError (naming the setting) unless degree >= max(k, 1),
// control_values >= max(degree + 1, 2(k + 1)) and 1 <= r <= min(degree, 2(k + 1)) — the last bound
// makes the objective determine what the constraints leave free.
BSplineFunction smoothest_bspline(double u0, double u1, std::span<const double> start, std::span<const double> end,
                                  const BSplineLawSettings& settings);

}  // namespace polarform
