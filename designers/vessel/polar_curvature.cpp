#include "designers/vessel/polar_curvature.h"

#include <cmath>

namespace polarform {

// DESIGN §4.4.
double polar_curvature(double r, double dr, double ddr) {
  const double q = r * r + dr * dr;
  return (r * r + 2 * dr * dr - r * ddr) / (q * std::sqrt(q));
}

// Derivatives of N·q^{-3/2} with N = R² + 2R'² − R R'' and q = R² + R'² (DESIGN §4.4).
PolarCurvature polar_curvature_with_gradient(double r, double dr, double ddr) {
  const double q = r * r + dr * dr, n = r * r + 2 * dr * dr - r * ddr;
  const double q32 = q * std::sqrt(q), kappa = n / q32;
  return {kappa, (2 * r - ddr) / q32 - 3 * kappa * r / q, 4 * dr / q32 - 3 * kappa * dr / q,
          -r / q32};
}

}  // namespace polarform
