// Conversion studies: how many arcs and control points each way of turning R(θ) into a NURBS
// curve needs as the tolerance tightens — the quasi-uniform quartic base (ours), the RQB base, and
// the baseline a CAD user would otherwise build (a cubic spline through points sampled from the
// exact profile, as many as needed) — each with its measured error; and the max angle deviation of
// RQB and quasi-uniform arcs against the arc angle (Bae 2002, Figure 5.4).
#pragma once

#include <functional>
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

struct StudyRow {
  double tolerance = 0.0;  // mm
  StudyMethodResult quartic, rqb, cubic;
};

// Log-spaced tolerances from `loosest` down to `tightest` (> 0), `per_decade` per decade.
std::vector<double> log_tolerances(double loosest, double tightest, int per_decade);

// One row per tolerance; `progress` (optional) gets the fraction done.
std::vector<StudyRow> tolerance_study(const PolarFunction& R, const std::vector<double>& tolerances,
                                      const std::function<void(double)>& progress = {});

struct DeviationRow {
  double arc_angle = 0.0;  // rad (2φ)
  double rqb = 0.0, quartic_minimax = 0.0, quartic_printed = 0.0;  // max |ξ(η) − 2φη|, rad
};

// Measured max angle deviation for arc angles from 2° to 180° in `count` log-spaced steps.
std::vector<DeviationRow> angle_deviation_study(int count);

}  // namespace polarform
