// Cubic spline interpolation with knots at the data parameters (NURBS Book §9.2.4, the cubic case
// of A9.1 with end conditions): N data values at increasing parameters t_1 < … < t_N give a cubic
// B-spline with N + 2 control values, clamped knots {t_1 ×4, t_2, …, t_{N−1}, t_N ×4}, through
// every value, closed by natural ends (C″ = 0) or given end derivatives. Kjellander's fairing (MIT
// §8.2.3-1) re-interpolates with it after every change of the data.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "src/nurbs/bspline.h"

namespace polarform {

struct CubicEnds {
  // Given first derivatives at t_1 and t_N (dim × 1); natural (C″ = 0) where absent.
  std::optional<Eigen::VectorXd> start_tangent, end_tangent;
};

// Bessel end tangents: the derivatives at t_1 and t_N of the parabolas through the first and the
// last three values (de Boor 1978, ch. IV; NURBS Book §9.2.2); third-order ends where natural ends
// force a wrong C″ = 0 on a curved run. Needs N >= 3 values at strictly increasing parameters.
CubicEnds bessel_ends(const Eigen::MatrixXd& values, const Eigen::VectorXd& parameters);

// values: dim × N (N >= 2), parameters strictly increasing. Throws InputError otherwise.
BSpline interpolate_cubic(const Eigen::MatrixXd& values, const Eigen::VectorXd& parameters,
                          const CubicEnds& ends = {});

}  // namespace polarform
