// The scan-cam report's account of the recovered design and of the motion's resolution: the
// "design" and "resolution" sections of report.json (documented in docs/cli-fit.md) and the
// angles of the recovered motions in the scan's cam frame, which the SVAJ plot shades.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "jobs/scan_cam/scan_cam_job.h"

namespace polarform {

// "design": the dwell rule, the phase, base radius, each motion (kind, chosen law, boundaries and
// lift with standard deviations, every candidate's rms residual and BIC, the laws the data cannot
// tell apart), the program as written and the re-designed cam's deviation from the scan.
nlohmann::ordered_json design_json(const ScanCamJobResult& r);
// "resolution": per derivative the signal, the propagated noise and whether it is resolved.
nlohmann::ordered_json resolution_json(const MotionResolution& resolution);

// A law as the report names it: "cycloidal", "scca (b 0.2, c 0.6, d 0.2)".
std::string law_label(const LawShape& shape);

// The derivative names of the resolution: "s", "v", "a", "j".
extern const char* const kDerivativeNames[4];

}  // namespace polarform
