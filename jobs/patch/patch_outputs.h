// The output bundle of a patch job: surface.igs/.stp/.x3d (the fitted patch), base.igs/.x3d (the
// base surface), decomposition.svg (its quad blanket), parameters.csv (every point's parameters on
// the base, its base distance and whether its quad was clamped, and its signed distance to the
// fit), thinned.ply (with thinning), deviation.ply, preview.svg, report.json and report.html. All
// files are written in one transaction: nothing is left half-written on an error.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "jobs/patch/patch_job.h"

namespace polarform {

nlohmann::ordered_json patch_report_json(const PatchJobResult& r,
                                         const std::vector<std::string>& files);

// Writes the bundle into dir (created if missing); returns the file names, sorted.
std::vector<std::string> write_patch_outputs(const PatchJobResult& r,
                                             const std::filesystem::path& dir);

}  // namespace polarform
