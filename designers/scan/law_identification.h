// Law identification of one rise or return of a recovered follower motion: every law polarform
// knows with a fixed shape — the six standard laws of motion_law.h, constant acceleration, the
// cubic and the double harmonic (whose return is its rise played backwards) — and the SCCA family
// with free fractions (b, c, d) (scca_law.h) is fitted with free boundary angles, start level and
// lift (law_fit.h) to the samples of the motion's window, and the law of least Bayesian information
// criterion BIC = RSS/σ² + k·ln n is chosen (Schwarz 1978; σ known: the scan's noise), so that
// SCCA, which holds five of these laws, wins only when its two extra parameters earn their
// penalty. The data cannot tell the chosen law from another when the other's RSS exceeds
// it by less than 9σ² (a difference of the two fitted curves within 3σ along the residual); SCCA
// is not listed against the laws it holds (harmonic, cycloidal, the modified ones, constant
// acceleration).
// The polynomial and B-spline laws are not candidates: with the zero endpoint derivatives of a
// rise between dwells, the minimal Hermite polynomials are the 3-4-5 and 4-5-6-7 laws; nor is
// constant velocity, whose blends make it a family like SCCA (not fitted yet).
#pragma once

#include <vector>

#include "designers/cam/motion_segment.h"
#include "designers/scan/follower_inversion.h"
#include "designers/scan/law_fit.h"
#include "designers/scan/motion_segmentation.h"

namespace polarform {

// The χ² margin below which two candidates cannot be told apart.
constexpr double kIndistinguishableChi2 = 9.0;

struct IdentifiedMotion {
  SegmentKind kind = SegmentKind::Rise;  // from the sign of the chosen lift
  std::vector<LawFit> candidates;        // kStandardLaws' order (law_identification.cpp), then SCCA
  std::vector<double> bic;               // per candidate
  std::size_t chosen = 0;
  std::vector<std::size_t> indistinguishable;  // candidates within the χ² margin of the chosen
  const LawFit& law() const { return candidates[chosen]; }
};

// The samples of `piece`'s window, angles unwrapped into it.
LawWindow motion_window(const FollowerSamples& samples, const MotionPiece& piece);

// noise: σ of the samples (the displacement fit's σ̂), mm. Throws InputError from fit_law when
// the window holds too few samples.
IdentifiedMotion identify_law(const FollowerSamples& samples, const MotionPiece& piece,
                              double noise);

}  // namespace polarform
