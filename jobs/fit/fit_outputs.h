// The fit job's output bundle, written into one directory: the fitted geometry as IGES, STEP and
// X3D (surface.* for surfaces, curve.* and curve.dxf for a polar profile), deviation.ply (every
// input point coloured by its signed distance, with the distance as the property "deviation"),
// preview.svg, report.json and report.html. Everything is rendered in memory first; each file is
// written atomically.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "jobs/fit/fit_job.h"

namespace polarform {

// Half-width of the deviation colour scale: p99 of |d| (at least 1e-9 mm).
double deviation_color_limit(const FitJobResult& r);

// "Outliers: 5 of 3005 points rejected at > 8 σ (σ = … mm, threshold … mm; largest … mm); the
// distances are of the 3000 points kept." — with --reject-outliers, the CLI summary and the HTML.
std::string outlier_summary(const FitJobResult& r);

// The report's fields of the fit (method and why, quadric, frame, degrees, nets, errors), without
// the version, command, timings and files.
nlohmann::ordered_json fit_report_fields(const FitJobResult& r);
// The whole report.
nlohmann::ordered_json fit_report_json(const FitJobResult& r,
                                       const std::vector<std::string>& files);

// Every output but deviation.ply rendered in memory, file name → content. The studio exports single
// files from it, so they equal the CLI's byte for byte.
std::map<std::string, std::string> render_fit_outputs(const FitJobResult& r);

// Writes every output into dir (created if missing) and returns the file names written.
std::vector<std::string> write_fit_outputs(const FitJobResult& r, const std::filesystem::path& dir);

}  // namespace polarform
