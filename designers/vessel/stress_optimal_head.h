// The head of a given depth whose largest membrane stress under internal pressure is smallest: a
// symmetric B-spline meridian R(θ) on [0, π] (θ about the junction-plane centre, as every vessel
// head here) tangent to the cylinder at the junctions, with R(π/2) = depth, found by NLopt's
// SLSQP as the minimax problem "min s subject to |N_φ|/p, |N_θ|/p <= s at every sample and κ >= 0"
// (membrane forces of membrane_stress.h; no inflection). The design goal beyond the presets of
// issue 16; compared with the ellipsoidal and torispherical heads of the same depth by
// head_depth_comparison.h.
#pragma once

#include <optional>
#include <string>

#include "src/nurbs/bspline.h"

namespace polarform {

struct StressOptimalSettings {
  int degree = 5;      // of R(θ)
  int ordinates = 24;  // control values on uniform clamped knots, mirrored about θ = π/2
  int samples = 121;   // constraint angles over [0, π/2], the apex included
  // κ of the meridian at the junctions, 1/mm: absent leaves it free (the optimiser chooses the
  // knuckle); 0 makes the head curvature-continuous with the cylinder.
  std::optional<double> junction_curvature;
  int max_iterations = 4000;  // objective-and-gradient evaluations allowed to NLopt

  bool operator==(const StressOptimalSettings&) const = default;
};

struct StressOptimalHead {
  BSplineFunction profile;  // R(θ), mm, on [0, π], symmetric about π/2
  // max(|N_φ|, |N_θ|)/p over the constraint samples, mm: the peak stress is p · peak_radius / t.
  double peak_radius = 0.0;
  int iterations = 0;       // objective-and-gradient evaluations by NLopt
  std::string termination;  // NLopt's reason for stopping
};

// Throws InputError unless radius > 0, 0 < depth <= 4 · radius and the settings are in range
// (degree 3..9, ordinates degree + 1..80 and >= 8, samples 16..2000), and NumericalError when
// SLSQP fails or leaves a constraint violated by more than 1e-6 of the radius.
StressOptimalHead minimum_peak_stress_head(double radius, double depth,
                                           const StressOptimalSettings& settings = {});

}  // namespace polarform
