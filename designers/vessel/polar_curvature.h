// Curvature of a polar curve r = R(θ) from R, R', R'' (DESIGN §4.4), with its partial derivatives,
// which are what the curvature synthesis needs for analytic gradients. Positive curvature means
// the curve turns towards the origin (a circle about the origin has κ = 1/R).
#pragma once

namespace polarform {

struct PolarCurvature {
  double kappa = 0.0;  // 1/length
  // ∂κ/∂R, ∂κ/∂R', ∂κ/∂R''.
  double d_r = 0.0, d_dr = 0.0, d_ddr = 0.0;
};

// κ = (R² + 2R'² − R R'') / (R² + R'²)^{3/2}; DESIGN §4.4. Needs R² + R'² > 0.
double polar_curvature(double r, double dr, double ddr);

// κ with its partial derivatives with respect to R, R' and R''.
PolarCurvature polar_curvature_with_gradient(double r, double dr, double ddr);

}  // namespace polarform
