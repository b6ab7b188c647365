// The measured flow-rate error of a base-circle arc: the largest deviation of the arc's polar angle
// ξ(η) from the uniform angle 2φη (Bae 2002, Figs. 5.2–5.4). The converter sizes its arcs by it,
// so it is located numerically on the actual arc, never taken from a fitted power law.
#pragma once

#include "src/base/arc_angle.h"

namespace polarform {

// max over η ∈ [0, 1] of |ξ(η) − 2φη| (radians) for an arc of half angle φ (0 < φ ≤ π/2); `rule`
// selects α for quartic arcs. The extrema are bracketed on a grid and refined by golden-section
// search to 1e-14 in η.
double max_angle_deviation(ArcKind kind, double half_angle, AlphaRule rule = AlphaRule::minimax);

}  // namespace polarform
