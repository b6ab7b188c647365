#include "designers/convert/polar_function.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace polarform {

bool PolarFunction::closed() const {
  return std::abs((end - start) - 2 * std::numbers::pi) <= 1e-12;
}

bool mirror_symmetric(const PolarFunction& R, double tol) {
  const double mid = 0.5 * (R.start + R.end);
  if (R.closed() || !std::binary_search(R.breakpoints.begin(), R.breakpoints.end(), mid))
    return false;
  for (int k = 0; k <= 256; ++k) {
    const double theta = R.start + (mid - R.start) * k / 256;
    if (!(std::abs(R(theta) - R(R.start + R.end - theta)) <= 1e-3 * tol)) return false;
  }
  return true;
}

double polar_angle_near(double x, double y, double near) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  const double a = std::atan2(y, x);
  const double d = a - near;
  // Most calls are within a half turn already (std::remainder would cost more than atan2).
  return d >= -std::numbers::pi && d <= std::numbers::pi
             ? a
             : a - kTwoPi * std::floor((d + std::numbers::pi) / kTwoPi);
}

}  // namespace polarform
