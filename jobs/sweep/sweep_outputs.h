// The output bundle of a sweep job: surface.igs/.stp/.x3d (the exact surfaces of revolution or
// extruded surfaces, or the skin of sections), profile.igs/.stp/.dxf/.svg (the meridian profile in
// its plane — z along the axis, r from it — or the section in its plane; the kind sections writes
// sections.igs/.svg instead: the section curves in space and in their station frames), solid.stp
// (an extrusion of one closed section: the closed B-rep solid), deviation.ply (every point with
// its signed distance), preview.svg, report.json and report.html.
// All files are written in one transaction: nothing is left half-written on an error.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "jobs/sweep/sweep_job.h"

namespace polarform {

nlohmann::ordered_json sweep_report_json(const SweepJobResult& r,
                                         const std::vector<std::string>& files);

// Writes the bundle into dir (created if missing); returns the file names, sorted.
std::vector<std::string> write_sweep_outputs(const SweepJobResult& r,
                                             const std::filesystem::path& dir);

}  // namespace polarform
