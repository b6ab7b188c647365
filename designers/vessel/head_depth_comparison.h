// Heads of one depth side by side under the same load: the peak membrane stress of a head (its
// largest |σ_φ| or |σ_θ| over the meridian, at the exact extrema of membrane_stresses) and the
// standard heads of that depth — the ellipsoidal head (ratio radius/depth) and the torispherical
// heads with 6 % and 17 % knuckles (of the diameter; 17 % with its crown is the usual 2:1
// equivalent) — that a designed head is judged against.
#pragma once

#include <string>
#include <vector>

#include "designers/convert/polar_function.h"
#include "designers/vessel/membrane_stress.h"

namespace polarform {

struct HeadStressSummary {
  std::string name;                    // e.g. "ellipsoidal 2:1"
  double depth = 0.0;                  // R(π/2), mm
  double peak_stress = 0.0;            // max |σ_φ|, |σ_θ| over the head, MPa
  double peak_theta = 0.0;             // rad, where it is
  double max_hoop_stress = 0.0;        // MPa
  double min_hoop_stress = 0.0;        // MPa (negative: compressive)
  double max_meridional_stress = 0.0;  // MPa
  double junction_curvature = 0.0;     // κ of the meridian at the junction, head side, 1/mm
  StressProfile stresses;              // the samples the figures above come from
};

// The stresses of `head` (a meridian R(θ) on [0, π] symmetric about π/2) under `load`.
HeadStressSummary head_stress_summary(std::string name, const PolarFunction& head,
                                      const VesselLoad& load);

struct DepthComparison {
  std::vector<HeadStressSummary> references;  // ellipsoidal, torispherical 6 %, torispherical 17 %
  std::vector<std::string> missing;           // the standard heads this depth has not, and why
};

// The standard heads of `depth` for load.radius; a torispherical head whose knuckle does not fit
// the depth is listed in `missing` with head_preset's reason.
DepthComparison standard_heads_of_depth(double depth, const VesselLoad& load);

}  // namespace polarform
