// Writing a fit job's results into one directory: the fitted geometry as IGES, STEP and X3D
// (surface.* for surfaces, curve.* for a polar profile), deviation.ply (every input point coloured
// by its signed distance, with the distance as the property "deviation"), preview.svg and
// report.json. Everything is rendered in memory first; each file is written atomically.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "jobs/fit/fit_job.h"

namespace polarform {

// Half-width of the deviation colour scale: p99 of |d| (at least 1e-9 mm).
double deviation_color_limit(const FitJobResult& r);

// The machine-readable report: method and why, quadric, frame, degrees, nets, errors, timings.
nlohmann::ordered_json fit_report_json(const FitJobResult& r,
                                       const std::vector<std::string>& files);

// Writes every output into dir (created if missing) and returns the file names written.
std::vector<std::string> write_fit_outputs(const FitJobResult& r, const std::filesystem::path& dir);

}  // namespace polarform
