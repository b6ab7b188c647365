// The output bundle of a pipe job: pipe.igs/.stp/.x3d (the pipe surface), spine.igs (the spine),
// curvature.svg (the spine's curvature κ against its length with 1/r marked and the stretches where
// κ·r >= 1 shaded), report.json and report.html. All files are written in one transaction.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "export/figure.h"
#include "jobs/pipe/pipe_job.h"

namespace polarform {

Figure pipe_curvature_figure(const PipeJobResult& r);

nlohmann::ordered_json pipe_report_json(const PipeJobResult& r,
                                        const std::vector<std::string>& files);

// Writes the bundle into dir (created if missing); returns the file names, sorted.
std::vector<std::string> write_pipe_outputs(const PipeJobResult& r,
                                            const std::filesystem::path& dir);

}  // namespace polarform
