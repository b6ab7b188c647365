#include "ui/studio/studio_options.h"

#include <CLI/CLI.hpp>
#include <regex>

namespace polarform::studio {
namespace {

constexpr int kMaxSize = 16384;  // pixels: the largest framebuffer of llvmpipe and common GPUs

}  // namespace

std::optional<StudioOptions> parse_options(int argc, char** argv, int& exit_code) {
  StudioOptions options;
  CLI::App app{
      "polarform-studio - the desktop app of polarform: design cams and vessel heads, fit scans"};
  std::string project, workspace, size;
  app.add_option("--project", project,
                 "a cam, vessel or fit project (XML), or a point cloud for the fit workspace")
      ->check(CLI::ExistingFile);
  app.add_option("--workspace", workspace, "workspace to show: cam, study, vessel or fit")
      ->check(CLI::IsMember({"cam", "study", "vessel", "fit"}));
  std::string script, state_dir;
  app.add_option("--script", script,
                 "run the actions of this file (open, drop, edit, undo, save-as, export, "
                 "screenshot, numbers, …; see docs/studio.md), then exit — or take the screenshot "
                 "or run the benchmark when asked as well")
      ->check(CLI::ExistingFile);
  app.add_option("--state-dir", state_dir,
                 "keep the app's state (last project, recent files, window layout) in this folder "
                 "instead of ~/.config/polarform-studio; headless runs keep it only when given");
  std::string screenshot;
  app.add_option("--screenshot", screenshot,
                 "render one frame after the computations settle to this PNG and exit");
  app.add_option("--bench-frames", options.bench_frames,
                 "render N frames while editing the design programmatically and print frame-time "
                 "statistics")
      ->check(CLI::Range(1, 1000000));
  app.add_option("--size", size, "window size WIDTHxHEIGHT in pixels (default 1600x1000)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    exit_code = app.exit(e) == 0 ? 0 : 2;
    return std::nullopt;
  }
  if (!project.empty()) options.project = project;
  if (!workspace.empty()) options.workspace = parse_workspace(workspace);
  if (!screenshot.empty()) options.screenshot = screenshot;
  if (!script.empty()) options.script = script;
  if (!state_dir.empty()) options.state_dir = state_dir;
  if (!size.empty()) {
    std::smatch m;
    if (!std::regex_match(size, m, std::regex(R"((\d{2,5})x(\d{2,5}))"))) {
      std::cerr << "polarform-studio: --size: expected WIDTHxHEIGHT such as 1600x1000, got '"
                << size << "'\n";
      exit_code = 2;
      return std::nullopt;
    }
    options.width = std::stoi(m[1]);
    options.height = std::stoi(m[2]);
    options.size_given = true;
    if (options.width < 320 || options.height < 240 || options.width > kMaxSize ||
        options.height > kMaxSize) {
      std::cerr << "polarform-studio: --size: from 320x240 to " << kMaxSize << "x" << kMaxSize
                << ", got " << size << "\n";
      exit_code = 2;
      return std::nullopt;
    }
  }
  exit_code = 0;
  return options;
}

}  // namespace polarform::studio
