// The tests' own measurement of a curve against an exact polar contour r = R(ψ), independent of
// how the curve was built and of the converter's measurement: the curve is sampled densely in its
// parameter and each point's radial error |ρ − R(ψ)| at its polar angle ψ is turned into the
// distance along the contour's normal (first order: × R/√(R² + R'²)).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "designers/convert/polar_function.h"

namespace polarform::test {

// Max distance of the curve point(u), u in [a, b], from the contour, over `samples` + 1 points.
inline double max_contour_distance(const std::function<Eigen::Vector2d(double)>& point, double a,
                                   double b, const PolarFunction& R, int samples = 20000) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  double worst = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const Eigen::Vector2d p = point(a + (b - a) * k / samples);
    double psi = std::atan2(p.y(), p.x());
    if (R.closed()) {
      psi = R.start + std::fmod(psi - R.start, kTwoPi);
      if (psi < R.start) psi += kTwoPi;
    } else {
      psi = std::clamp(psi, R.start, R.end);
    }
    double d[2];
    R.derivatives(psi, 1, d);
    worst = std::max(worst, std::abs(p.norm() - d[0]) * std::abs(d[0]) / std::hypot(d[0], d[1]));
  }
  return worst;
}

}  // namespace polarform::test
