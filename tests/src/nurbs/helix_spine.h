// A helix (a cos t, a sin t, c t), t in [0, turns·2π], as the cubic spline through `samples`
// points with knots at their parameters and the exact end tangents (NURBS Book §9.2.4): a helix
// is not rational, so the pipe and frame tests use this dense approximation of it.
#pragma once

#include <cmath>
#include <numbers>

#include "src/nurbs/curve_interpolation.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform::test {

inline NurbsCurve3d helix_spline(double a, double c, double turns, int samples) {
  const double end = turns * 2 * std::numbers::pi;
  Eigen::MatrixXd values(3, samples);
  Eigen::VectorXd t(samples);
  for (int k = 0; k < samples; ++k) {
    t[k] = end * k / (samples - 1);
    values.col(k) << a * std::cos(t[k]), a * std::sin(t[k]), c * t[k];
  }
  CubicEnds ends;
  ends.start_tangent = Eigen::Vector3d(0, a, c);
  ends.end_tangent = Eigen::Vector3d(-a * std::sin(end), a * std::cos(end), c);
  const BSpline s = interpolate_cubic(values, t, ends);
  Eigen::MatrixXd h(4, s.size());
  h << s.coefs(), Eigen::RowVectorXd::Ones(s.size());
  return NurbsCurve3d(BSpline(3, s.knots(), h));
}

}  // namespace polarform::test
