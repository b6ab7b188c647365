// The first step of the conversion: R(θ) as a B-spline function F(θ) within a share of the
// tolerance. Exact forms are used as they are (with the knots their continuity allows removed);
// any other R is fitted segment by segment — between its breakpoints, where it is smooth — by a
// quintic B-spline with simple knots that meets R's one-sided value, slope and curvature at both
// segment ends exactly and fits it in between by constrained least squares, refined until the
// measured error meets the budget.
#pragma once

#include "designers/convert/polar_function.h"
#include "src/nurbs/bspline.h"

namespace polarform {

struct FunctionSpline {
  BSplineFunction spline;  // over [R.start, R.end]
  double max_error = 0.0;  // measured max |F(θ) − R(θ)|, 0 for exact forms
  bool exact = false;
};

// F within tol of R (measured). A constant R gives a degree-0 F so that products stay at the
// base circle's degree.
FunctionSpline represent_as_bspline(const PolarFunction& R, double tol);

// Max |F(θ) − R(θ)| over F's domain: `per_span` samples per knot span, then golden-section
// refinement around the three largest samples.
double max_function_error(const BSplineFunction& F, const PolarFunction& R, int per_span = 6);

}  // namespace polarform
