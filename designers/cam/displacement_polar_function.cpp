#include "designers/cam/displacement_polar_function.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace polarform {

BSplineFunction displacement_bspline_in_cam_frame(const BSplineFunction& f, Rotation rotation, double base) {
  Knots knots = f.knots();
  Eigen::VectorXd values = f.values().array() + base;  // partition of unity: adding a constant
  if (rotation == Rotation::Clockwise) {  // φ = θ + π/2
    for (double& k : knots) k += std::numbers::pi / 2;
  } else {  // φ = π/2 - θ: mirrored knots, reversed coefficients
    std::reverse(knots.begin(), knots.end());
    for (double& k : knots) k = std::numbers::pi / 2 - k;
    values.reverseInPlace();
  }
  return BSplineFunction(f.degree(), std::move(knots), values);
}

// Chain rule through the affine map θ = σ(π/2 - φ): F^(k)(φ) = (-σ)^k s^(k)(θ).
PolarFunction displacement_polar_function(const CamProgram& program, Rotation rotation, double base) {
  const double two_pi = 2 * std::numbers::pi;
  PolarFunction f;
  f.start = rotation == Rotation::Clockwise ? std::numbers::pi / 2 : std::numbers::pi / 2 - two_pi;
  f.end = f.start + two_pi;
  for (double theta : program.smoothness_breaks())
    f.breakpoints.push_back(follower_polar_angle(theta, rotation));
  std::sort(f.breakpoints.begin(), f.breakpoints.end());
  f.derivatives = [program, rotation, base](double phi, int d, double* out) {
    program.derivatives(cam_angle(phi, rotation), d, out);  // periodic in θ
    out[0] += base;
    const double chain = -sense(rotation);
    double factor = chain;
    for (int k = 1; k <= d; ++k, factor *= chain) out[k] *= factor;
  };
  if (const std::optional<BSplineFunction> exact = program.exact())
    f.exact = displacement_bspline_in_cam_frame(*exact, rotation, base);
  return f;
}

}  // namespace polarform
