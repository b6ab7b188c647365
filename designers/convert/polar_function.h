// PolarFunction: the converter's input — a single-valued polar function R(θ) on [start, end] with
// exact derivatives, the angles where its smoothness may drop, and its exact B-spline form when one
// exists (polynomial motion laws). Cam laws, follower contours and vessel profiles all reach the
// NURBS converter through this one type.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "src/nurbs/bspline.h"

namespace polarform {

struct PolarFunction {
  // Angular domain in radians; the function is closed (periodic) when end - start == 2π.
  double start = 0.0;
  double end = 0.0;
  // Interior angles (increasing, strictly inside (start, end)) where a derivative may jump,
  // e.g. motion-segment boundaries. Arc and knot breakpoints honour them.
  std::vector<double> breakpoints;
  // Writes R(θ), R'(θ), ..., R^(d)(θ) into out[0..d], d <= 3, exactly (no finite differences).
  // At a breakpoint the derivatives may be taken from either side.
  std::function<void(double theta, int d, double* out)> derivatives;
  // An exact B-spline form of R over [start, end], when one exists; the converter then uses it
  // instead of approximating.
  std::optional<BSplineFunction> exact;

  double operator()(double theta) const {
    double r;
    derivatives(theta, 0, &r);
    return r;
  }
  bool closed() const;
};

// Whether r = R(θ) is its own mirror image in the line θ = m = (start + end)/2, which is then a
// breakpoint (a vessel head's meridian over [0, π], mirrored in its axis): R(start + end − θ) =
// R(θ) to a thousandth of tol at 257 angles of [start, m].
bool mirror_symmetric(const PolarFunction& R, double tol);

// The polar angle of the point (x, y) that lies nearest to `near` (within π of it): the angle a
// curve point has when the curve follows the polar angle `near` approximately.
double polar_angle_near(double x, double y, double near);

}  // namespace polarform
