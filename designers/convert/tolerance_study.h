// Conversion studies: how many arcs and control points each way of turning R(θ) into a NURBS
// curve needs as the tolerance tightens — the quasi-uniform quartic base (ours), the RQB base, and
// the baseline a CAD user would otherwise build (a cubic spline through points sampled from the
// exact profile, as many as needed) — each with its measured error; polarform's compact profiles
// (the compacted exact form, the degree-3 profile) beside the peers (issue 14), Open CASCADE's
// GeomAPI_PointsToBSpline and SISL's s1961, with the control-point ratios; and the max angle
// deviation of RQB and quasi-uniform arcs against the arc angle (Bae 2002, Figure 5.4).
#pragma once

#include <functional>
#include <limits>
#include <vector>

#include "designers/convert/polar_function.h"
#include "src/base/arc_angle.h"

namespace polarform {

struct StudyMethodResult {
  int arcs = 0;            // base-circle arcs (0 for the point-interpolation baseline)
  int points = 0;          // interpolated points (baseline only)
  int degree = 0;
  int control_points = 0;
  double max_radial_error = 0.0;  // mm, measured
};

// A peer's fit (occt_peer.h, sisl_peer.h): found = false when no fit of its tolerance ladder
// measured within ε (or the peer is not in this build).
struct StudyPeerResult {
  bool found = false;
  int degree = 0;
  int control_points = 0;
  double max_radial_error = 0.0;  // mm, measured
  double peer_tolerance = 0.0;    // mm, the tolerance that gave it (OCCT's Tol3D, SISL's eeps)
};

// Control points of polarform's compact profiles over the best peer's (the fewest among all the
// found peer fits, OCCT's and SISL's) and over each peer's degree 3; NaN where no peer (that peer)
// found a curve.
struct StudyPeerRatios {
  static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  double exact_to_best = kNone, degree3_to_best = kNone, degree3_to_occt_degree3 = kNone,
         degree3_to_sisl_degree3 = kNone;
};

struct StudyRow {
  double tolerance = 0.0;  // mm
  StudyMethodResult quartic, rqb, cubic;
  StudyMethodResult exact;  // the exact form as compacted by default (refitted, polar_conversion.h)
  StudyMethodResult degree3;  // the degree-3 profile, knots by need (degree_limited.h)
  bool peers = false;         // the peer fits below were run (those in this build)
  StudyPeerResult occt_degree3, occt_best;  // GeomAPI_PointsToBSpline, degree 3 and 3..8
  StudyPeerResult sisl_degree3, sisl_best;  // s1961, degree 3 and the fewest of degrees 3..8
  StudyPeerRatios ratios;
};

struct StudyOptions {
  bool peers = true;  // run the peer fits (those available: occt_peer.h, sisl_peer.h)
};

// Log-spaced tolerances from `loosest` down to `tightest` (> 0), `per_decade` per decade.
std::vector<double> log_tolerances(double loosest, double tightest, int per_decade);

// One row per tolerance; `progress` (optional) gets the fraction done.
std::vector<StudyRow> tolerance_study(const PolarFunction& R, const std::vector<double>& tolerances,
                                      const std::function<void(double)>& progress = {},
                                      const StudyOptions& options = {});

struct DeviationRow {
  double arc_angle = 0.0;  // rad (2φ)
  double rqb = 0.0, quartic_minimax = 0.0, quartic_printed = 0.0;  // max |ξ(η) − 2φη|, rad
};

// Measured max angle deviation for arc angles from 2° to 180° in `count` log-spaced steps.
std::vector<DeviationRow> angle_deviation_study(int count);

}  // namespace polarform
