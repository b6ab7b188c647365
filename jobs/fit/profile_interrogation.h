// What a designer reads first about a fitted profile's fairness (Patrikalakis, MIT 2.158J lecture
// 8; spec M2): its signed curvature around the centre, its inflections, and the jump of the
// degree-th derivative at every knot — where the curve is unfair. The numbers of curvature.svg and
// of report.json's "interrogation".
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "src/fit/polar_curve_fit.h"
#include "src/fit/profile_fairing.h"

namespace polarform {

struct ProfileInterrogation {
  // At each sample: the curve parameter, the point, its polar angle about the centre (deg), the
  // signed κ (1/mm) and dκ/du.
  std::vector<double> u, x, y, angle_deg, curvature, curvature_derivative;
  struct Place {
    double u, angle_deg, value;  // curve parameter, polar angle, jump (mm/unit^p) or κ
  };
  std::vector<Place> inflections;       // value: 0
  std::vector<Place> derivative_jumps;  // value: |ΔC^(p)| at each interior knot
  int order = 0;                        // p, the curve's degree
};

// κ at `samples` parameters, the inflections and the knots' jumps of a fitted polar curve (the
// fit job's profile, scan-cam's cam profile).
ProfileInterrogation interrogate_profile(const PolarCurveFit& fit, int samples = 2000);

// curvature.csv: one row per sample, u, x [mm], y [mm], polar angle [deg], kappa [1/mm],
// dkappa/du [1/mm].
std::string interrogation_csv(const ProfileInterrogation& interrogation);

// report.json's "interrogation": inflections_deg, derivative_order, max_derivative_jump and
// max_derivative_jump_at_deg.
nlohmann::ordered_json interrogation_json(const ProfileInterrogation& interrogation);

// report.json's "fairing": method, tolerance_mm, passes, knots_faired[{u, u_deg, jump_before,
// jump_after, bound_mm}], max_jump_before/after and measured_deviation_mm.
nlohmann::ordered_json fairing_json(const ProfileFairing& fairing);

}  // namespace polarform
