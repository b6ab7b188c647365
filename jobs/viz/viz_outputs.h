// Writing a viz job's results into one directory: the field surface S = (s·F + d)·B as IGES and
// STEP, the coloured scene surface.x3d (see export/x3d_field_scene.h), control_values.csv (every control point
// with the value it carries), preview.svg and report.json; rendered in memory first, each file
// written atomically.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "jobs/viz/viz_job.h"

namespace polarform {

nlohmann::ordered_json viz_report_json(const VizJobResult& r,
                                       const std::vector<std::string>& files);

// Writes every output into dir (created if missing) and returns the file names written.
std::vector<std::string> write_viz_outputs(const VizJobResult& r, const std::filesystem::path& dir);

}  // namespace polarform
