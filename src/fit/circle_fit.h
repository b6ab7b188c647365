// Algebraic circle fit for the centre of polar curve fitting when none is given: Taubin's
// normalisation of A(x²+y²) + Bx + Cy + D = 0 (Taubin 1991; Chernov, "Circular and linear
// regression", 2010, §5.9) on centred data, a 3 x 3 generalised eigenproblem. It is unbiased for
// partial arcs to first order, unlike the plain Kåsa fit.
#pragma once

#include <Eigen/Core>

namespace polarform {

struct CircleFit {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double radius = 0.0;
  double rms = 0.0;  // RMS of |p − centre| − radius
};

// Needs at least 3 points not all on one line; throws InputError otherwise.
CircleFit fit_circle(const Eigen::Matrix2Xd& points);

}  // namespace polarform
