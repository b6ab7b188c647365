// `polarform study`: sweep the conversion tolerance for a cam design and compare the quasi-uniform
// quartic base, the RQB base, a cubic spline through sampled points, and polarform's compact
// profiles (exact form, degree 3) against the peers' fits, Open CASCADE's and SISL's.
#include <cmath>
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
  bool no_peers = false;
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

// A peer's control points, or "-" where it found no curve within ε.
std::string peer_count(const StudyPeerResult& p) {
  return p.found ? std::to_string(p.control_points) : "-";
}

std::string ratio_text(double ratio) {
  char text[16];
  std::snprintf(text, sizeof text, "%.2f", ratio);
  return std::isfinite(ratio) ? text : "-";
}

// Arcs (or points) / control points per method, then (with peers) control points against OCCT's
// and SISL's, and the ratios to the best peer fit.
void print_table(const StudyJobResult& r) {
  std::printf("%12s  %18s  %18s  %18s  %13s  %5s", "tolerance mm", "quartic arcs/ctrl",
              "rqb arcs/ctrl", "cubic points/ctrl", "exact arcs/ctrl", "deg 3");
  if (r.peers)
    std::printf("  %6s  %9s  %6s  %9s  %11s  %11s", "occt 3", "occt 3..8", "sisl 3", "sisl 3..8",
                "exact/best", "deg 3/best");
  std::printf("\n");
  for (const StudyRow& row : r.rows) {
    std::printf("%12.3g  %8d/%-9d  %8d/%-9d  %8d/%-9d  %6d/%-6d  %5d", row.tolerance,
                row.quartic.arcs, row.quartic.control_points, row.rqb.arcs, row.rqb.control_points,
                row.cubic.points, row.cubic.control_points, row.exact.arcs,
                row.exact.control_points, row.degree3.control_points);
    if (r.peers)
      std::printf("  %6s  %9s  %6s  %9s  %11s  %11s", peer_count(row.occt_degree3).c_str(),
                  peer_count(row.occt_best).c_str(), peer_count(row.sisl_degree3).c_str(),
                  peer_count(row.sisl_best).c_str(), ratio_text(row.ratios.exact_to_best).c_str(),
                  ratio_text(row.ratios.degree3_to_best).c_str());
    std::printf("\n");
  }
}

void run(const StudyArgs& a) {
  const auto [loosest, tightest] = parse_range(a.range);
  const std::vector<double> tolerances = log_tolerances(loosest, tightest, a.per_decade);
  std::vector<std::string> warnings;
  const CamProject project = read_cam_project(a.design, warnings, unknown_names_policy(a.lenient));
  for (const std::string& w : warnings) std::cerr << "polarform: warning: " << w << "\n";
  const StudyOptions options{!a.no_peers};
  ProgressBar bar("study", !a.quiet);
  const StudyJobResult r = for_design(
      a.design, [&] { return run_study_job(project, tolerances, std::ref(bar), options); });
  bar.finish();
  const std::string name = std::filesystem::path(a.design).stem().string();
  const std::vector<std::string> files = write_study_outputs(r, name, a.out);
  if (a.quiet) return;
  print_table(r);
  if (!r.peers) std::printf("%s\n", missing_peers_note(options).c_str());
  std::printf("wrote %zu files to %s (%.1f s)\n", files.size(),
              std::filesystem::absolute(a.out).string().c_str(), r.seconds);
}

}  // namespace

void add_study_command(CLI::App& app) {
  auto args = std::make_shared<StudyArgs>();
  CLI::App* cmd = app.add_subcommand(
      "study",
      "Sweep the conversion tolerance of a cam design (log steps) and compare the quasi-uniform\n"
      "quartic base, the RQB base, a cubic spline through sampled points, the compacted exact\n"
      "form and the degree-3 profile, and these against the peers: Open CASCADE's\n"
      "GeomAPI_PointsToBSpline (degree 3 and 3..8) and SISL's s1961 (degree 3 and the best of\n"
      "3..8). Writes study.csv, study.svg, deviation.csv, deviation.svg (max angle deviation vs\n"
      "arc angle) and report.json.");
  cmd->add_option("design", args->design, "cam project file (XML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out", args->out, "output directory (created if missing)")->required();
  cmd->add_option("--tol", args->range, "tolerance range LOOSEST:TIGHTEST in mm")
      ->capture_default_str();
  cmd->add_option("--steps-per-decade", args->per_decade, "tolerances per decade")
      ->check(CLI::Range(1, 20))
      ->capture_default_str();
  cmd->add_flag("--no-peers", args->no_peers,
                "leave out the peer fits, Open CASCADE's (1-2 s per tolerance and fit) and SISL's");
  cmd->add_flag("--quiet,-q", args->quiet, "print nothing but warnings and errors");
  cmd->add_flag("--lenient", args->lenient, kLenientHelp);
  cmd->callback([args] { run(*args); });
}

}  // namespace polarform::cli
