// What a designer reads first about a fitted profile's fairness (Patrikalakis, MIT 2.158J lecture
// 8; spec M2): its signed curvature around the centre, its inflections, and the jump of the
// degree-th derivative at every knot — where the curve is unfair. The numbers of curvature.svg and
// of report.json's "interrogation".
#pragma once

#include <vector>

#include "jobs/fit/fit_job.h"

namespace polarform {

struct ProfileInterrogation {
  std::vector<double> angle_deg, curvature;  // polar angle about the centre, signed κ (1/mm)
  struct Place {
    double u, angle_deg, value;  // curve parameter, polar angle, jump (mm/unit^p) or κ
  };
  std::vector<Place> inflections;       // value: 0
  std::vector<Place> derivative_jumps;  // value: |ΔC^(p)| at each interior knot
  int order = 0;                        // p, the curve's degree
};

// κ at `samples` parameters, the inflections and the knots' jumps of the fitted curve.
ProfileInterrogation interrogate_profile(const ProfileFit& fit, int samples = 2000);

}  // namespace polarform
