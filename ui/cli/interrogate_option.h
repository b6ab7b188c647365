// `--interrogate [gauss|mean|absolute]` of fit, sweep and patch (MIT §8.2.4): curvature maps and
// reflection lines of the surfaces a command writes; bare, the Gaussian curvature is shown.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "jobs/interrogation/surface_interrogation.h"

namespace polarform::cli {

void add_interrogate_option(CLI::App& command, std::string& value);

// Empty: not asked; "gauss", "mean", "absolute" (or bare): that quantity. InputError otherwise.
std::optional<CurvatureQuantity> interrogate_option(const std::string& value);

}  // namespace polarform::cli
