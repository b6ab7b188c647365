// The subcommands of the polarform CLI, one registration function per cmd_*.cpp.
#pragma once

#include <CLI/CLI.hpp>

namespace polarform::cli {

// Adds every subcommand to the app.
void register_commands(CLI::App& app);

// One per cmd_*.cpp.
void add_cam_command(CLI::App& app);
void add_study_command(CLI::App& app);
void add_fit_command(CLI::App& app);
void add_viz_command(CLI::App& app);
void add_scan_cam_command(CLI::App& app);

}  // namespace polarform::cli
