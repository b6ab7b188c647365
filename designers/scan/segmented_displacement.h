// The follower displacement refitted piece by piece along a recovered design (design_recovery.h),
// for fairing: a clamped B-spline of the displacement fit's degree on [0, 2π] whose knots are the
// fit's uniform ones plus every boundary of the recovered motion with multiplicity p − c, c the
// continuity the identified laws have there (C2 where a law's acceleration vanishes at its end, C1
// where it does not; a knot of multiplicity m leaves C^(p−m), NURBS Book §2.2), held constant over
// each recovered dwell (its control values tied: partition of unity) and periodic to C^(p−1) at the
// seam (to the boundary's continuity when one falls on it). The motions are smoothed by the
// quintic smoothing-spline penalty λ∫s‴² (Wahba 1990, §1.2), λ chosen by Morozov's discrepancy
// principle, RSS(λ) = n·σ̂² (Morozov 1966; Hansen 2010, §5.2), with σ̂² = RSS/(n − tr H) of the
// GCV fit on the same pieces (Craven & Wahba 1979) — a noise level that fit always leaves below
// n·σ̂², so the discrepancy is always reachable, and more smoothing than GCV's, which predicts s
// best but leaves noise that s″ amplifies. The penalised systems for every λ come from one
// simultaneous diagonalisation (Demmler & Reinsch 1975).
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
  double sd = 0.0;     // its standard deviation from the law fits, rad
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
  double dof = 0.0;                    // effective parameters tr(H) at it
  double rss = 0.0;                    // Σ residual², mm²
  double target_rss = 0.0;             // n·σ̂², mm²
  double noise = 0.0;                  // σ̂ from the GCV fit on the same pieces, mm
  double gcv_lambda = 0.0, gcv_dof = 0.0;  // GCV's choice on the same pieces
  bool discrepancy_met = false;  // RSS = n·σ̂² reached (else the nearest end of the λ range)
  std::size_t breaks = 0, dwells = 0;  // as used (breaks joined to the seam count as one)
};

// A break goes on a uniform knot within 3 of its standard deviations (or 0.05 span) of it — the
// data cannot tell them apart — and uniform knots within a quarter span of a break are left out.
// Throws InputError for bad options or fewer than two samples per span, NumericalError when the
// penalised system is singular.
SegmentedDisplacement fit_segmented_displacement(const FollowerSamples& samples,
                                                 const DisplacementPieces& pieces,
                                                 const SegmentedDisplacementOptions& options = {});

}  // namespace polarform
