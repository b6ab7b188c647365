// Fairing the follower displacement recovered from a scan (MIT 13.472J §8.2.3 on s(θ), whose
// derivatives are the SVAJ): Farin's knot removal and re-insertion on the periodic B-spline of
// displacement_fit.h (no control value within its degree of the ends moves, so the seam at θ = 0
// stays C^(p−1)); Kjellander's needs a cubic and is refused on the default quintic. The move of
// s is measured, not assumed.
#pragma once

#include <vector>

#include "designers/scan/scanned_cam.h"
#include "src/fit/curve_fairing.h"
#include "src/fit/profile_fairing.h"

namespace polarform {

struct DisplacementFairing {
  FairingMethod method = FairingMethod::farin;
  double tolerance = 0.0;  // mm, as used: 3 × the displacement fit's noise σ̂ unless given
  std::vector<FairingStep> steps;  // u: the cam angle θ of the knot faired, rad
  double max_jump_before = 0.0, max_jump_after = 0.0;  // of s's p-th derivative
  double measured_deviation = 0.0;  // max |s_faired − s| over 20 001 cam angles, mm
};

// Replaces scan.displacement.height by the faired s (the rest height and base radius stay those
// of the fit). Throws InputError for Kjellander on a non-cubic s.
DisplacementFairing fair_scanned_displacement(ScannedCam& scan,
                                              const ProfileFairingOptions& options);

}  // namespace polarform
