// Writing a cam job's results: CAD files (IGES, STEP, DXF, X3D, optionally a STEP solid), plots
// (SVG), the SVAJ table (CSV) and the reports (report.json, report.html) into one directory.
// Every file is written atomically; nothing is written before everything has been computed.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "jobs/cam/cam_job.h"

namespace polarform {

struct CamOutputOptions {
  std::string design_name = "cam";        // shown in reports and file headers
  std::optional<double> solid_thickness;  // mm: also write the plate cam as a solid
  std::optional<double> bore_diameter;    // mm, with the solid
};

// The machine-readable report (field names documented in docs/file-formats.md).
nlohmann::ordered_json cam_report_json(const CamJobResult& r, const std::vector<std::string>& files);

// Writes every output into dir (created if missing) and returns the file names written.
std::vector<std::string> write_cam_outputs(const CamJobResult& r, const std::filesystem::path& dir,
                                           const CamOutputOptions& options = {});

}  // namespace polarform
