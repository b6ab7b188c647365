// SINTEF's SISL as the second peer converter (issue 14): s1961, a B-spline approximation of a
// point set within a tolerance (the piecewise linear interpolant reduced by knot removal, raised
// to the order asked and reduced again), fitted to the same dense samples of the contour
// r = R(θ) as Open CASCADE's peer and verified by polarform's own dense measurement
// (peer_fit.h). Compiled only where SISL is found (POLARFORM_HAVE_SISL); kSislPeersAvailable says
// so, so that callers test it with `if constexpr` rather than `#if`.
#pragma once

#include "designers/convert/peer_fit.h"
#include "designers/convert/polar_function.h"

namespace polarform {

#ifdef POLARFORM_HAVE_SISL
inline constexpr bool kSislPeersAvailable = true;
#else
inline constexpr bool kSislPeersAvailable = false;
#endif

// How s1961 is called (its own arguments; the defaults are the study's, chosen on r = 40 + 5 cos 3θ
// mm: chord length gave 3-8 % more control points than θ, a linear share of 0.1 gave 40-60 % more
// than 0, and 5 to 20 iterations the same counts).
struct S1961Options {
  int parametrization = 3;    // ipar: 1 chord length (SISL's default), 2 uniform, 3 the angle θ
  double linear_share = 0.0;  // afctol: the share of eeps spent on the linear reduction, in [0, 1]
  int iterations = 10;        // itmax: iterations of each knot-removal (data reduction) stage
  // Points of the contour handed to s1961 (peer_contour_samples); 0: the peers' 1441, multiplied
  // until the samples' polygon lies within ε/10 of the contour (s1961 approximates the polygon: at
  // 0.1 µm the 1441 samples' polygon of r = 40 + 5 cos 3θ is about 0.2 µm off and no fit verifies),
  // at most 14401; none (found = false without a call) when even 14401 samples' polygon lies more
  // than ε/2 from the contour.
  int samples = 0;
};

// PeerCurve sisl_s1961(R, degree, tol, options)
//
// SISL's s1961 on the samples of peer_contour_samples (options.samples), order degree + 1, for the
// componentwise
// tolerance eeps = tol·{2, 1.4, 1, 0.7, 0.5, 0.35, 0.25} in turn (s1961 bounds the deviation from
// the samples' polygon, not from R), the first curve whose measured max radial error is <= tol
// returned (verified_on_ladder). A closed R is fitted as a closed periodic curve (iopen = -1,
// C^{degree-1} across the seam), an open one as an open curve keeping its end points (iopen = 1,
// ilend = irend = 1). The curve is returned clamped (a periodic one clipped to its period, as many
// control points as SISL's in), its parameter mapped linearly onto [R.start, R.end].
//
// Inputs:
//   R       the profile (closed or open)
//   degree  1 <= degree <= 20 (3 for a cubic; the study's best runs 3..8)
//   tol     the tolerance ε, mm (> 0)
// Output:
//   the verified curve with its control points, degree, measured error and eeps (peer_tolerance);
//   found = false when no eeps of the ladder gave one (a call with jstat < 0 is skipped).
PeerCurve sisl_s1961(const PolarFunction& R, int degree, double tol,
                     const S1961Options& options = {});

// PeerCurve sisl_s1961_best(R, deg_min, deg_max, tol)
//
// sisl_s1961 at every degree of [deg_min, deg_max]; the verified curve with the fewest control
// points (the lower degree among equals), found = false when no degree gave one.
PeerCurve sisl_s1961_best(const PolarFunction& R, int deg_min, int deg_max, double tol);

}  // namespace polarform
