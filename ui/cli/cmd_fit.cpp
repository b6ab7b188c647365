// `polarform fit`: fit a scanned point cloud with a polar NURBS curve (a planar profile) or a
// spherical / cylindrical NURBS surface (Bae 2002, ch. 2-4) and write the geometry, a deviation
// cloud, a preview plot and a report.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>

#include "jobs/fit/fit_outputs.h"
#include "src/error.h"
#include "ui/cli/commands.h"
#include "ui/cli/fairing_arguments.h"
#include "ui/cli/fit_arguments.h"
#include "ui/cli/interrogate_option.h"
#include "ui/cli/progress_bar.h"

namespace polarform::cli {

namespace {

struct FitArgs {
  std::string scan, out;
  // Empty: not given (the project's value, or the default).
  std::string method, closed, pole, degree, ctrl, tol, tol_measure, center, axis;
  std::string fairness, lambda, base, revolution, fair, fair_tol, fair_passes, interrogate;
  std::string threads = "2";
  bool skip_bad = false, reject_outliers = false, quiet = false, lenient = false;
};

// "X,Y,Z", or "X,Y" (Z = 0) where `planar_ok`.
Eigen::Vector3d vector3(const std::string& option, const std::string& text, bool planar_ok) {
  const std::vector<double> v = parse_numbers(option, text, planar_ok ? 2 : 3, 3);
  return {v[0], v[1], v.size() == 3 ? v[2] : 0.0};
}

// The options given on the command line, over `o` (a project's or the defaults).
FitJobOptions job_options(const FitArgs& a, FitJobOptions o) {
  constexpr FitJobMethod methods[] = {FitJobMethod::automatic, FitJobMethod::polar,
                                      FitJobMethod::spherical, FitJobMethod::cylindrical};
  constexpr Closure closures[] = {Closure::automatic, Closure::closed, Closure::open};
  constexpr PoleTreatment poles[] = {PoleTreatment::none, PoleTreatment::g0, PoleTreatment::g1,
                                     PoleTreatment::cap};
  constexpr ToleranceMeasure measures[] = {ToleranceMeasure::max, ToleranceMeasure::p99,
                                           ToleranceMeasure::p95, ToleranceMeasure::rms};
  if (!a.method.empty())
    o.method =
        methods[parse_choice("--method", a.method, {"auto", "polar", "spherical", "cylindrical"})];
  if (!a.closed.empty())
    o.closure = closures[parse_choice("--closed", a.closed, {"auto", "yes", "no"})];
  if (!a.pole.empty()) o.pole = poles[parse_choice("--pole", a.pole, {"none", "g0", "g1", "cap"})];
  if (!a.degree.empty()) o.degree = parse_int_pair("--degree", a.degree, 1, 9);
  if (!a.ctrl.empty() && !a.tol.empty())
    throw InputError("--ctrl and --tol: give one (a fixed control net or a tolerance to refine to)");
  if (!a.ctrl.empty()) {
    o.ctrl = parse_int_pair("--ctrl", a.ctrl, 2, 2000);
    o.tolerance.reset();
  }
  if (!a.tol.empty()) {
    o.tolerance = parse_numbers("--tol", a.tol, 1, 1)[0];
    if (!(*o.tolerance > 0))
      throw InputError("--tol '" + a.tol + "': expected a positive number of mm");
    o.ctrl.reset();
  }
  if (!a.tol_measure.empty())
    o.measure =
        measures[parse_choice("--tol-measure", a.tol_measure, {"max", "p99", "p95", "rms"})];
  if (!a.center.empty()) o.center = vector3("--center", a.center, true);
  if (!a.axis.empty()) o.axis = vector3("--axis", a.axis, false);
  if (!a.fairness.empty())
    o.fairness = static_cast<FairnessOptions::Mode>(
        parse_choice("--fairness", a.fairness, {"fixed", "relative", "gcv"}));
  if (!a.lambda.empty()) {
    o.fairness_weight = parse_numbers("--lambda", a.lambda, 1, 1)[0];
    if (!(o.fairness_weight > 0) || !std::isfinite(o.fairness_weight))
      throw InputError("--lambda '" + a.lambda + "': expected a positive number");
  }
  if (!a.base.empty())
    o.base = parse_choice("--base", a.base, {"rqb", "quartic"}) == 1 ? ArcKind::quartic
                                                                   : ArcKind::rqb;
  if (!a.revolution.empty())
    o.revolution = static_cast<RevolutionMode>(
        parse_choice("--revolution", a.revolution, {"auto", "yes", "no"}));
  o.fairing = fairing_options(a.fair, a.fair_tol, a.fair_passes);
  if (const auto q = interrogate_option(a.interrogate)) o.interrogate = q;
  o.threads = parse_int_pair("--threads", a.threads, 1, 256).first;
  o.skip_bad = o.skip_bad || a.skip_bad;
  o.reject_outliers = o.reject_outliers || a.reject_outliers;
  return o;
}

void run(const FitArgs& a) {
  // A project file (.xml) names the scan and its options; flags given here override them.
  std::filesystem::path scan = a.scan;
  FitJobOptions defaults;
  if (std::filesystem::path(a.scan).extension() == ".xml") {
    std::vector<std::string> warnings;
    const FitProject project = read_fit_project(a.scan, warnings, unknown_names_policy(a.lenient));
    for (const std::string& w : warnings) std::cerr << "polarform: warning: " << w << "\n";
    scan = scan_path(project, a.scan);
    defaults = fit_job_options(project);
  }
  FitJobOptions o = job_options(a, defaults);
  ProgressBar reading("reading ", !a.quiet), fitting("fitting ", !a.quiet);
  o.read_progress = [&reading](double f) {
    reading(f);
    if (f >= 1.0) reading.finish();
  };
  o.fit_progress = std::ref(fitting);
  const FitJobResult r = run_fit_job(scan, o);
  fitting.finish();
  const std::vector<std::string> files = write_fit_outputs(r, a.out);
  if (r.dropped > 0)
    std::cerr << "polarform: warning: " << r.dropped << " bad records skipped in "
              << scan.string() << "\n";
  for (const std::string& w : r.warnings)
    std::cerr << "polarform: warning: " << scan.string() << ": " << w << "\n";
  if (a.quiet) return;
  const FitReport& rep = r.report();
  std::printf("%s fit: %s\n", r.method.c_str(), r.reason.c_str());
  if (const ProfileFit* profile = std::get_if<ProfileFit>(&r.fit))
    std::printf("F degree %d, %d control values; NURBS curve degree %d, %d control points\n",
                rep.degree_v, rep.size_v, profile->curve.degree(), profile->curve.size());
  else
    std::printf(
        "F degree (%d, %d), %d x %d control values; NURBS surface degree (%d, %d), %d x %d control "
        "points\n",
        rep.degree_u, rep.degree_v, rep.size_u, rep.size_v, rep.nurbs_degree_u, rep.nurbs_degree_v,
        rep.nurbs_size_u, rep.nurbs_size_v);
  if (r.reject_outliers) std::printf("%s\n", outlier_summary(r).c_str());
  std::printf(
      "distance to the fit over %zu points: rms %.4g mm, p95 %.4g mm, p99 %.4g mm, max %.4g mm\n",
      rep.error.count, rep.error.rms, rep.error.p95, rep.error.p99, rep.error.max);
  std::printf("wrote %zu files to %s (%.0f ms)\n", files.size(),
              std::filesystem::absolute(a.out).string().c_str(), r.seconds * 1e3);
}

}  // namespace

void add_fit_command(CLI::App& app) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fit",
      "Fit a scanned point cloud (xyz/csv, PLY, STL, OBJ, OFF) with an exact NURBS: a polar curve "
      "for a\n"
      "planar profile, or a spherical / cylindrical surface. Writes surface.igs/.stp/.x3d "
      "(curve.igs/\n"
      ".stp/.x3d/.dxf for a profile), deviation.ply (points coloured by signed distance),\n"
      "preview.svg, report.json and report.html.");
  cmd->add_option("scan", args->scan,
                  "point-cloud file, or a fit project (.xml, see docs/file-formats.md) naming one")
      ->required();
  cmd->add_option("--out", args->out, "output directory (created if missing)")->required();
  cmd->add_option("--method", args->method,
                  "auto|polar|spherical|cylindrical (default auto: a planar cloud is a profile, "
                  "else the best-fit quadric decides)");
  cmd->add_option("--closed", args->closed, "auto|yes|no: close the fit around the axis (default auto)");
  cmd->add_option(
      "--pole", args->pole,
      "none|g0|g1|cap: both poles of a spherical fit (default: G0 where the data reaches a "
      "pole)");
  cmd->add_option("--degree", args->degree,
                  "p[,q]: degrees of F along u (φ or z) and v (θ); a curve uses the last");
  cmd->add_option("--ctrl", args->ctrl,
                  "n[,m]: control values of F along u and v (default: chosen by GCV over net "
                  "sizes, at most one coefficient per 4 points)");
  cmd->add_option("--tol", args->tol,
                  "mm: refine F until the distance measure meets this (instead of --ctrl); a "
                  "tolerance below the data's noise estimate is refused");
  cmd->add_option("--tol-measure", args->tol_measure,
                  "max|p99|p95|rms: the statistic --tol bounds (default max)");
  cmd->add_option("--center", args->center,
                  "X,Y[,Z]: origin of the fit's frame in mm (profiles: the polar centre); alone, "
                  "a surface fit refines the axis through it");
  cmd->add_option("--axis", args->axis,
                  "X,Y,Z: axis k of the fit's frame (profiles: the plane normal); alone, a "
                  "surface fit finds its line (cylindrical) or centre (spherical)");
  cmd->add_option("--fairness", args->fairness,
                  "fixed|relative|gcv: how the fairing weight λ is chosen (default relative: "
                  "--lambda times the data's scale; fixed: λ = --lambda; gcv: generalised "
                  "cross-validation)");
  cmd->add_option("--lambda", args->lambda,
                  "the fairing weight of --fairness fixed or relative (default 1e-7)");
  cmd->add_option("--base", args->base,
                  "rqb|quartic: arcs of the base circles (default rqb; quartic: quasi-uniform "
                  "quartic arcs, Blanc–Schlick)");
  cmd->add_option("--revolution", args->revolution,
                  "auto|yes|no: make F constant around the axis — an exact surface of revolution, "
                  "sphere-like form or circle (default auto: when an F-test of F(u) against "
                  "F(u, v) finds no variation beyond the noise at the 0.1 % level)");
  add_interrogate_option(*cmd, args->interrogate);
  cmd->add_option(
      "--fair", args->fair,
      "kjellander|farin: fair F after the fit (MIT §8.2.3-8.2.4): a profile's (curvature.svg "
      "shows before and after) or a surface's rows and columns");
  cmd->add_option("--fair-tol", args->fair_tol,
                  "how far fairing may move the curve [mm] (default 3 × the fit's rms error)");
  cmd->add_option("--fair-passes", args->fair_passes,
                  "at most this many knots faired (default 100)");
  cmd->add_option("--threads", args->threads, "worker threads (default 2)");
  cmd->add_flag("--skip-bad", args->skip_bad,
                "skip unparsable or non-finite records instead of stopping");
  cmd->add_flag("--reject-outliers", args->reject_outliers,
                "leave points more than 8 robust σ off the fit out of it (trimmed least squares, "
                "refitted until stable) instead of refusing a scan with a few");
  cmd->add_flag("--quiet,-q", args->quiet, "no progress bars and no summary");
  cmd->add_flag("--lenient", args->lenient, kLenientHelp);
  cmd->callback([args] { run(*args); });
}

}  // namespace polarform::cli
