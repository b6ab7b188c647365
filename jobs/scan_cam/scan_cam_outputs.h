// Writing a scan-cam job's results into one directory: the recovered profile (in the cam frame) as
// IGES, STEP, DXF and X3D, optionally the recovered design as a cam project, the recovered motion
// svaj.csv (with the nominal's and the differences when there is a nominal), the plots (svaj.svg,
// deviation.svg, profile.svg, svaj_difference.svg), report.json and report.html. Everything is
// rendered in memory first; each file is written atomically.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "jobs/scan_cam/scan_cam_job.h"

namespace polarform {

// The machine-readable report (fields documented in docs/cli-fit.md).
// project: the recovered design's project file when one is written (empty: none).
nlohmann::ordered_json scan_cam_report_json(const ScanCamJobResult& r,
                                            const std::vector<std::string>& files,
                                            const std::filesystem::path& project = {});

// Writes every output into dir (created if missing) and returns the file names written; with a
// project path, also the recovered design as a cam project there (scan_cam_project.h), written
// last and atomically. A design that was not recovered, or a project path whose folder does not
// exist, is refused (InputError naming --write-project) before anything is written.
std::vector<std::string> write_scan_cam_outputs(const ScanCamJobResult& r,
                                                const std::filesystem::path& dir,
                                                const std::filesystem::path& project = {});

}  // namespace polarform
