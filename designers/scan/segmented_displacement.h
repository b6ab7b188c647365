// The follower displacement refitted piece by piece along a recovered design (design_recovery.h),
// for fairing: a clamped B-spline of the displacement fit's degree on [0, 2π] whose knots are the
// fit's uniform ones plus every boundary of the recovered motion with multiplicity p − c, c the
// continuity the identified laws have there (C2 where a law's acceleration vanishes at its end, C1
// where it does not; NURBS Book §2.2: a knot of multiplicity m leaves C^(p−m)), held constant over
// each recovered dwell (its control values tied: partition of unity) and periodic to C^(p−1) at the
// seam (to the boundary's continuity when a boundary falls on it). The motions are smoothed by the
// quintic smoothing-spline penalty λ∫s‴² (Wahba 1990, §1.2) with λ chosen by Morozov's
// discrepancy principle: the residual sum of squares equals n·σ̂², σ̂ the displacement fit's noise
// (Morozov 1966; Hansen 2010, §5.2) — the fit takes out no more than the noise the scan states,
// where GCV, tuned to predict s, leaves noise that its second derivative amplifies.
#pragma once

#include <vector>

#include "designers/scan/design_recovery.h"
#include "designers/scan/follower_inversion.h"
#include "src/nurbs/bspline.h"

namespace polarform {

// A boundary of the recovered motion and the continuity of s across it.
struct DisplacementBreak {
  double theta = 0.0;  // rad in [0, 2π)
  int continuity = 2;  // s is C^continuity there (0 ≤ continuity < degree)
};

// Where the recovered design says s is constant, and where its pieces meet.
struct DisplacementPieces {
  std::vector<DisplacementBreak> breaks;  // increasing θ
  // [start, end] rad, both in [0, 2π); end < start for a dwell that holds θ = 0.
  std::vector<std::pair<double, double>> dwells;
};

// The pieces of a recovered design's motion in the scan's cam angles (design angle + phase): each
// dwell with a break at each end, each shared boundary of two motions a break (at the midpoint of
// their two fitted ends, as the design joins them). A law's continuity at an end is read from its
// normalised shape (law_fit.h): C2 when S′ and S″ vanish there, C1 when only S′ does, else C0.
DisplacementPieces displacement_pieces(const RecoveredDesign& design);

struct SegmentedDisplacementOptions {
  int degree = 5;
  int spans = 180;  // the uniform knots (as the displacement fit's)
};

struct SegmentedDisplacement {
  BSplineFunction height;              // y0 + s(θ) on [0, 2π]
  double lambda = 0.0;                 // the penalty weight the discrepancy principle chose
  double dof = 0.0;                    // effective parameters tr(H)
  double rss = 0.0;                    // Σ residual², mm²
  double target_rss = 0.0;             // n·σ̂², mm²
  bool discrepancy_met = false;        // RSS = n·σ̂² reached (else the least-penalised fit)
  std::size_t breaks = 0, dwells = 0;  // as used (after snapping to the uniform knots)
};

// noise: σ̂ of the samples (mm, > 0). Throws InputError for bad options or too few samples.
SegmentedDisplacement fit_segmented_displacement(const FollowerSamples& samples,
                                                 const DisplacementPieces& pieces, double noise,
                                                 const SegmentedDisplacementOptions& options = {});

}  // namespace polarform
