// The subcommands of the polarform CLI, one registration function per cmd_*.cpp, and what they
// share.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "src/error.h"

namespace polarform::cli {

// Adds every subcommand to the app.
void register_commands(CLI::App& app);

// Runs a job on the design read from `design`; an InputError it raises (an infeasible design: an
// undercut, an offset beyond the prime circle, …) is raised again with the file name in front.
template <class Job>
auto for_design(const std::string& design, Job&& job) {
  try {
    return job();
  } catch (const InputError& e) {
    throw InputError(design + ": " + e.what());
  }
}

// One per cmd_*.cpp.
void add_cam_command(CLI::App& app);
void add_study_command(CLI::App& app);
void add_vessel_command(CLI::App& app);
void add_fit_command(CLI::App& app);
void add_viz_command(CLI::App& app);
void add_scan_cam_command(CLI::App& app);

}  // namespace polarform::cli
