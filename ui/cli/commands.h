// The subcommands of the polarform CLI, one registration function per cmd_*.cpp, and what they
// share.
#pragma once

#include <CLI/CLI.hpp>
#include <stdexcept>
#include <string>

#include "jobs/project/unknown_names.h"
#include "src/error.h"

namespace polarform::cli {

// Ends a command whose work is done (every output written) with exit status 3: the inspected part
// is out of its tolerance. QC scripts gate on the status; main prints the message.
class OutOfTolerance : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

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

// The help of --lenient, on every command that reads a project file.
inline constexpr const char* kLenientHelp =
    "read a project with unknown attributes or elements, or of a newer version, ignoring what "
    "this polarform does not know (a warning for each); without it they are an error";

// What a command does with a project's unknown names: refuse them, or warn with --lenient.
inline UnknownNames unknown_names_policy(bool lenient) {
  return lenient ? UnknownNames::warn : UnknownNames::refuse;
}

// One per cmd_*.cpp.
void add_cam_command(CLI::App& app);
void add_study_command(CLI::App& app);
void add_vessel_command(CLI::App& app);
void add_fit_command(CLI::App& app);
void add_viz_command(CLI::App& app);
void add_scan_cam_command(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_patch_command(CLI::App& app);
void add_pipe_command(CLI::App& app);

}  // namespace polarform::cli
