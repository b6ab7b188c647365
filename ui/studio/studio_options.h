// The command line of polarform-studio: an optional project (a cam, vessel or fit project XML, or a
// point cloud for the fit workspace) and workspace, and the headless modes — run a script of
// actions (--script, see studio_script.h), render one settled frame to a PNG (--screenshot), or
// N frames under scripted edits with frame-time statistics (--bench-frames) — at a given window
// size, with the app's state kept in a given folder (--state-dir).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "ui/studio/workspace_kind.h"

namespace polarform::studio {

struct StudioOptions {
  std::optional<std::filesystem::path> project;
  std::optional<WorkspaceKind> workspace;
  std::optional<std::filesystem::path> script;  // run first, then the screenshot or benchmark
  std::optional<std::filesystem::path> screenshot;
  int bench_frames = 0;
  int width = 1600, height = 1000;
  bool size_given = false;
  // Where the app keeps its state (last project, recent files, layout); headless runs keep none
  // unless given one.
  std::optional<std::filesystem::path> state_dir;
  bool headless() const { return script || screenshot || bench_frames > 0; }
};

// Parses argv; on --help or a usage error prints to stdout/stderr and returns the exit code in
// `exit_code` with nullopt.
std::optional<StudioOptions> parse_options(int argc, char** argv, int& exit_code);

}  // namespace polarform::studio
