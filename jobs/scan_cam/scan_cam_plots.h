// The scan-cam job's figures: the recovered SVAJ against cam angle (with the nominal's, dashed,
// and the displacement samples), their differences from the nominal, the profile deviation
// against cam angle (fitted profile and scanned points, ±3σ̂ noise floor, ±tolerance), and the
// profile in the cam frame with the scan and the nominal contour.
#pragma once

#include "export/figure.h"
#include "jobs/scan_cam/scan_cam_job.h"

namespace polarform {

Figure scan_svaj_figure(const ScanCamJobResult& r);
Figure scan_svaj_difference_figure(const ScanCamJobResult& r);  // needs a nominal
Figure scan_deviation_figure(const ScanCamJobResult& r);
Figure scan_profile_figure(const ScanCamJobResult& r);
// --fair: the recovered acceleration before (grey) and after fairing s(θ), the nominal's dashed,
// and the p-th derivative jumps at the knots faired before and after.
Figure scan_fairing_figure(const ScanCamJobResult& r);  // needs r.fairing

// The recovered s, s', s'', s''' (mm/rad^k) on `count` uniform cam angles over a revolution.
std::array<std::vector<double>, 4> recovered_svaj(const ScannedCam& scan,
                                                  const std::vector<double>& theta);

}  // namespace polarform
