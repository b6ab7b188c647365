// The half spheroid x²/a² + z²/b² = 1 as a polar head meridian R(θ) = ab / √(b²cos²θ + a²sin²θ)
// on [0, π], with R' = −R³ (a² − b²) sin 2θ / (2a²b²): the closed form the vessel tests measure
// placements and volumes against.
#pragma once

#include <cmath>
#include <numbers>

#include "designers/convert/polar_function.h"

namespace polarform::test {

inline PolarFunction spheroid_meridian(double a, double b) {
  PolarFunction f;
  f.start = 0.0;
  f.end = std::numbers::pi;
  f.derivatives = [a, b](double t, int d, double* out) {
    const double c = std::cos(t), s = std::sin(t);
    out[0] = a * b / std::sqrt(b * b * c * c + a * a * s * s);
    if (d >= 1)
      out[1] = -std::pow(out[0], 3) * (a * a - b * b) * std::sin(2 * t) / (2 * a * a * b * b);
  };
  return f;
}

}  // namespace polarform::test
