// The volume a polar head R(θ) encloses with its junction plane — its A half θ ∈ [0, π/2] revolved
// about the axis — by Pappus on the sector ½R²dθ whose centroid lies ⅔R cosθ from the axis:
// V = (2π/3) ∫₀^{π/2} R(θ)³ cosθ dθ; and the area of that surface, A = 2π ∫₀^{π/2} R cosθ √(R² +
// R'²) dθ.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "designers/convert/polar_function.h"
#include "designers/vessel/head_measures.h"
#include "designers/vessel/synthesis_space.h"

namespace polarform {

// Volume (mm³) and inner area (mm²) of the head R(θ), by Gauss–Legendre on 256 parts of [0, π/2]
// (R is smooth there; round-off level for the B-spline heads of the synthesis).
HeadMeasures polar_head_measures(const PolarFunction& R);

// V in the synthesis unknowns x (ordinates = L · map · x), in units of L³, with its gradient: the
// cubic V(x) = (2π/3) Σ_q w_q cosθ_q (a_q · x)³ over Gauss nodes θ_q that are exact for it on every
// knot span (a_q the basis row at θ_q through the map).
class HeadVolumeConstraint {
 public:
  explicit HeadVolumeConstraint(const SynthesisSpace& space);
  double value(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const;

 private:
  Eigen::MatrixXd rows_;     // a_q
  Eigen::VectorXd weights_;  // (2π/3) w_q cosθ_q
};

}  // namespace polarform
