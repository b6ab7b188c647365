// The smoothing weight λ of a curvature synthesis chosen from its targets (issue 16), so that the
// design never rings between them:
// - shape-preserving: the smallest λ (the closest fit) whose curvature κ(θ) has no turning point
//   and no inflection that the targets' own sequence lacks (turning points counted with a
//   hysteresis of 1 % of the targets' curvature range, so that round-off ripple on a plateau does
//   not count) — the shape-preservation criterion of monotone interpolation (Fritsch & Carlson
//   1980) applied to the choice of a smoothing spline's weight;
// - tolerance: the largest λ (the smallest curvature variation) whose every target is met within
//   kappa_tolerance — Reinsch's (1967) criterion with a maximum instead of a sum.
// Both search λ on decades of [1e-10, 1e4] and refine the bracket by bisection in log λ.
#pragma once

#include <optional>
#include <string>

#include "designers/vessel/curvature_synthesis.h"

namespace polarform {

struct SmoothingChoice {
  SmoothingRule rule = SmoothingRule::fixed;  // the λ chosen is the result's smoothing
  int trials = 0;                 // syntheses run to choose it
  bool met = true;                // false: no λ tried met the rule; the best one is used
  int target_turning_points = 0;  // of the targets' sequence (shape-preserving)
  int turning_points = 0;         // of the design's κ(θ), same hysteresis
  double max_residual = 0.0;      // max |κ(θ_k) − κ_k| of the design, 1/mm
};

// Synthesises with problem.settings.smoothing when the rule is fixed, else with the λ the rule
// chooses (`hint`: a previous choice to search around first). Passes on synthesize_profile's
// errors when every λ tried fails.
SynthesisResult synthesize_with_chosen_smoothing(const SynthesisProblem& problem,
                                                 SmoothingChoice& choice,
                                                 std::optional<double> hint = std::nullopt);

// "fixed", "shape-preserving", "tolerance".
const char* smoothing_rule_name(SmoothingRule rule);

}  // namespace polarform
