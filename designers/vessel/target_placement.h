// Curvature targets given by the meridian's arc length s from junction A or by its meridian angle
// φ (the shell normal's angle against the axis) placed at polar angles θ on a head R(θ): s(θ) =
// ∫₀^θ √(R² + R'²) dθ, and φ(θ) = π − θ − atan2(R, R') (the tangent of R(θ)(cosθ, sinθ) turns by
// θ + atan2(R, R'); φ = 90° at θ = 0 with R' = 0, 0 at an apex with R' = 0, −90° at θ = π).
#pragma once

#include <string>
#include <vector>

#include "designers/convert/polar_function.h"
#include "designers/vessel/synthesis_problem.h"

namespace polarform {

// Sets θ of every target placed by arc length or meridian angle from R (targets by polar angle are
// left as they are); returns the largest change of θ, rad. Throws InputError naming the target
// (1-based) when R's meridian over [0, π] does not reach its s or φ.
double place_targets(std::vector<CurvatureTarget>& targets, const PolarFunction& R);

// The meridian of the circle R = radius (the synthesis's start): θ = s / radius, θ = π/2 − φ.
void place_targets_on_circle(std::vector<CurvatureTarget>& targets, double radius);

// "θ", "s", "φ": the attribute a place is given by.
const char* target_place_symbol(TargetPlace place);

}  // namespace polarform
