#include "designers/convert/polar_function.h"

#include <cmath>
#include <numbers>

namespace polarform {

bool PolarFunction::closed() const {
  return std::abs((end - start) - 2 * std::numbers::pi) <= 1e-12;
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
