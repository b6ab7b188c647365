// `polarform study`: sweep the conversion tolerance for a cam design and compare the quasi-uniform
// quartic base, the RQB base and a cubic spline through sampled points.
#include <cstdio>
#include <iostream>
#include <sstream>

#include "jobs/study/study_job.h"
#include "src/number_text.h"
#include "ui/cli/commands.h"
#include "ui/cli/progress_bar.h"

namespace polarform::cli {

namespace {

struct StudyArgs {
  std::string design;
  std::string out;
  std::string range = "1e-2:1e-7";
  int per_decade = 2;
  bool quiet = false;
  bool lenient = false;
};

std::pair<double, double> parse_range(const std::string& text) {
  const auto colon = text.find(':');
  double loosest = 0, tightest = 0;
  try {
    if (colon == std::string::npos) throw std::invalid_argument("no colon");
    std::size_t used = 0;
    loosest = std::stod(text.substr(0, colon), &used);
    if (used != colon) throw std::invalid_argument("trailing text");
    const std::string rest = text.substr(colon + 1);
    tightest = std::stod(rest, &used);
    if (used != rest.size()) throw std::invalid_argument("trailing text");
  } catch (const std::exception&) {
    throw InputError("--tol '" + text + "': expected LOOSEST:TIGHTEST in mm, e.g. 1e-2:1e-7");
  }
  if (!(tightest >= kMinTolerance && loosest >= tightest))
    throw InputError("--tol '" + text + "': expected LOOSEST >= TIGHTEST >= " +
                     format_round_trip(kMinTolerance) + " mm");
  return {loosest, tightest};
}

void run(const StudyArgs& a) {
  const auto [loosest, tightest] = parse_range(a.range);
  const std::vector<double> tolerances = log_tolerances(loosest, tightest, a.per_decade);
  std::vector<std::string> warnings;
  const CamProject project = read_cam_project(a.design, warnings, unknown_names_policy(a.lenient));
  for (const std::string& w : warnings) std::cerr << "polarform: warning: " << w << "\n";
  ProgressBar bar("study", !a.quiet);
  const StudyJobResult r =
      for_design(a.design, [&] { return run_study_job(project, tolerances, std::ref(bar)); });
  bar.finish();
  const std::string name = std::filesystem::path(a.design).stem().string();
  const std::vector<std::string> files = write_study_outputs(r, name, a.out);
  if (a.quiet) return;
  std::printf("%12s  %18s  %18s  %18s\n", "tolerance mm", "quartic arcs/ctrl", "rqb arcs/ctrl",
              "cubic points/ctrl");
  for (const StudyRow& row : r.rows)
    std::printf("%12.3g  %8d/%-9d  %8d/%-9d  %8d/%-9d\n", row.tolerance, row.quartic.arcs,
                row.quartic.control_points, row.rqb.arcs, row.rqb.control_points, row.cubic.points,
                row.cubic.control_points);
  std::printf("wrote %zu files to %s (%.1f s)\n", files.size(),
              std::filesystem::absolute(a.out).string().c_str(), r.seconds);
}

}  // namespace

void add_study_command(CLI::App& app) {
  auto args = std::make_shared<StudyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "study",
      "Sweep the conversion tolerance of a cam design (log steps) and compare the quasi-uniform\n"
      "quartic base, the RQB base and a cubic spline through sampled points. Writes study.csv,\n"
      "study.svg, deviation.csv, deviation.svg (max angle deviation vs arc angle) and report.json.");
  cmd->add_option("design", args->design, "cam project file (XML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out", args->out, "output directory (created if missing)")->required();
  cmd->add_option("--tol", args->range, "tolerance range LOOSEST:TIGHTEST in mm")
      ->capture_default_str();
  cmd->add_option("--steps-per-decade", args->per_decade, "tolerances per decade")
      ->check(CLI::Range(1, 20))
      ->capture_default_str();
  cmd->add_flag("--quiet,-q", args->quiet, "print nothing but warnings and errors");
  cmd->add_flag("--lenient", args->lenient, kLenientHelp);
  cmd->callback([args] { run(*args); });
}

}  // namespace polarform::cli
