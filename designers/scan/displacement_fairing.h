// Fairing the follower displacement recovered from a scan (MIT 13.472J §8.2.3 on s(θ), whose
// derivatives are the SVAJ). Farin's: s is first refitted along the design recovered from the scan
// (segmented_displacement.h: constant over the dwells, the laws' continuity at the boundaries,
// the motions smoothed to Morozov's discrepancy n·σ̂² rather than by GCV), then its simple knots are
// removed and re-inserted (Farin's knot removal, MIT 13.472J (8.19)–(8.33); the boundary knots,
// multiple, are left alone, as is every control value within the degree of the ends, so the seam
// stays as refitted). When no design can be recovered, the refit cannot reach the discrepancy
// (its least-penalised residual exceeds n·σ̂²), or it would move s beyond the tolerance, s is
// faired as fitted. Kjellander's needs a cubic and is refused on the default
// quintic. The move of s is measured, not assumed.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "designers/scan/scanned_cam.h"
#include "designers/scan/segmented_displacement.h"
#include "src/fit/curve_fairing.h"
#include "src/fit/profile_fairing.h"

namespace polarform {

struct DisplacementFairing {
  FairingMethod method = FairingMethod::farin;
  double tolerance = 0.0;  // mm, as used: 3 × the displacement fit's noise σ̂ unless given
  // Farin: the refit along the recovered design, or why s was faired as fitted.
  std::optional<SegmentedDisplacement> refit;
  std::string refit_skipped;
  double refit_deviation = 0.0;    // max |s_refit − s| over 20 001 cam angles, mm
  std::vector<FairingStep> steps;  // u: the cam angle θ of the knot faired, rad
  // Of s's p-th derivative: before, over the knots of s as fitted; after, over the simple knots
  // of the faired s (the boundary knots of a refit carry the jumps the laws have there).
  double max_jump_before = 0.0, max_jump_after = 0.0;
  double measured_deviation =
      0.0;  // max |s_faired − s| over 20 001 cam angles, mm (refit included)
};

// Replaces scan.displacement.height by the faired s (the rest height and base radius stay those
// of the fit). Throws InputError for Kjellander on a non-cubic s.
DisplacementFairing fair_scanned_displacement(ScannedCam& scan,
                                              const ProfileFairingOptions& options);

}  // namespace polarform
