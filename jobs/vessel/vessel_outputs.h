// Writing a vessel job's results into one directory: the profile (IGES, STEP, DXF), the head
// surface (IGES, STEP), the whole vessel as a STEP shell, plots (SVG), the curvature and stress
// samples (CSV) and the reports (report.json, field names in docs/cli-vessel.md, and report.html).
// Everything is rendered in memory first and every file is written atomically.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "jobs/vessel/vessel_job.h"

namespace polarform {

struct VesselOutputOptions {
  std::string design_name = "vessel";  // shown in reports and file headers
};

// The machine-readable report (field names and units documented in docs/cli-vessel.md).
nlohmann::ordered_json vessel_report_json(const VesselJobResult& r,
                                          const std::vector<std::string>& files);

// Writes every output into dir (created if missing) and returns the file names written.
std::vector<std::string> write_vessel_outputs(const VesselJobResult& r,
                                              const std::filesystem::path& dir,
                                              const VesselOutputOptions& options = {});

}  // namespace polarform
