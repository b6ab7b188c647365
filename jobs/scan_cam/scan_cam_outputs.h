// Writing a scan-cam job's results into one directory: the recovered profile (in the cam frame) as
// IGES, STEP, DXF and X3D, the recovered motion svaj.csv (with the nominal's and the differences
// when there is a nominal), the plots (svaj.svg, deviation.svg, profile.svg, svaj_difference.svg),
// report.json and report.html. Everything is rendered in memory first; each file is written
// atomically.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "jobs/scan_cam/scan_cam_job.h"

namespace polarform {

// The machine-readable report (fields documented in docs/cli-fit.md).
nlohmann::ordered_json scan_cam_report_json(const ScanCamJobResult& r,
                                            const std::vector<std::string>& files);

// Writes every output into dir (created if missing) and returns the file names written.
std::vector<std::string> write_scan_cam_outputs(const ScanCamJobResult& r,
                                                const std::filesystem::path& dir);

}  // namespace polarform
