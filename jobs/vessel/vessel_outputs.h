// The vessel job's output bundle, written into one directory: the profile (IGES, STEP, DXF), the
// head surface (IGES, STEP), the whole vessel as a STEP shell, plots (SVG), the curvature and
// stress samples (CSV) and the reports (report.json, field names in docs/cli-vessel.md, and
// report.html). Everything is rendered in memory first and every file is written atomically.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "jobs/vessel/vessel_job.h"
#include "jobs/vessel/vessel_report.h"

namespace polarform {

struct VesselOutputOptions {
  std::string design_name = "vessel";  // shown in reports and file headers
};

// Every output of the job rendered in memory, file name → content: the CAD files, figures, CSV
// samples and both reports. The studio exports single files from it, so they equal the CLI's.
std::map<std::string, std::string> render_vessel_outputs(const VesselJobResult& r,
                                                         const VesselOutputOptions& options = {});

// Writes every output into dir (created if missing) and returns the file names written.
std::vector<std::string> write_vessel_outputs(const VesselJobResult& r,
                                              const std::filesystem::path& dir,
                                              const VesselOutputOptions& options = {});

}  // namespace polarform
