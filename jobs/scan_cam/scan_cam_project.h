// The design a scan-cam job recovered, as a cam project (jobs/project/cam_project.h): the
// scan's follower, rotation and base radius, the recovered segments and laws in the design's
// frame (designers/scan/design_recovery.h), and the nominal's speed and conversion settings when
// there is one (the defaults otherwise). `polarform cam` on it reproduces the scanned profile to
// the deviation the report states.
#pragma once

#include <filesystem>

#include "jobs/project/cam_project.h"
#include "jobs/scan_cam/scan_cam_job.h"

namespace polarform {

// Throws InputError naming --write-project and the reason when no design was recovered.
CamProject recovered_cam_project(const ScanCamJobResult& r);

}  // namespace polarform
