// A scanned cam against its nominal design, both in the nominal's cam frame after phase
// alignment: the deviation of the fitted profile from the nominal contour at the nominal's contact
// point C(θ) for every cam angle θ, radial (R_fit − |C| along the ray, as the converter measures)
// and normal (signed closest-point distance, + where the part has more material), the radial and
// (first-order) normal deviation of every scanned point, and the differences of the recovered s, v,
// a, j from the nominal program's.
#pragma once

#include <array>
#include <vector>

#include "designers/scan/scanned_cam.h"
#include "src/fit/error_stats.h"

namespace polarform {

struct NominalComparison {
  std::vector<double> theta;           // cam angles, rad (uniform grid over a revolution)
  std::vector<double> radial, normal;  // profile deviation at C(θ), mm
  ErrorStats radial_stats, normal_stats;
  Eigen::VectorXd point_radial;  // per contour point of the scan: |q| − R_nom(ψ_q), mm
  ErrorStats point_stats;
  // Per contour point: the radial deviation along the nominal's normal (first order), mm.
  Eigen::VectorXd point_normal;
  ErrorStats point_normal_stats;
  // Recovered minus nominal s, s', s'', s''' on the grid (mm/rad^k), and their statistics.
  std::array<std::vector<double>, 4> svaj_difference;
  std::array<ErrorStats, 4> svaj_stats;
  std::array<std::vector<double>, 4> nominal_svaj;  // the nominal's s, s', s'', s''' on the grid
};

// samples >= 16 cam angles. phase: the nominal's cam angle is θ − phase at the scan's θ (its
// frame is the scan's turned by σ·phase: a design recovered from the scan, design_recovery.h);
// 0 for a nominal the scan was aligned to.
NominalComparison compare_to_nominal(const ScannedCam& scan, const PlateCam& nominal,
                                     int samples = 3600, double phase = 0.0);

}  // namespace polarform
