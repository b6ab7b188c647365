// `polarform patch`: fit a scanned patch that is not single-valued about a centre or an axis by a
// parametric B-spline surface (Piegl & Tiller 2001): a base surface spanned by the boundary
// parametrises every point through its quad blanket, then the surface is fitted with the boundary
// fixed. Exit 1 when --tol is not met (the bundle is written, the report says by how much).
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "jobs/patch/patch_outputs.h"
#include "src/error.h"
#include "src/number_text.h"
#include "ui/cli/commands.h"
#include "ui/cli/fit_arguments.h"
#include "ui/cli/interrogate_option.h"
#include "ui/cli/progress_bar.h"

namespace polarform::cli {

namespace {

struct PatchArgs {
  std::string scan, out, boundary, grid, base = "bilinear", base_share, base_ctrl, base_degree,
                                         cross_scale = "auto", decomposition_tol, split = "extent",
                                         search = "grid3d", polish = "yes", thin, degree = "3,3",
                                         ctrl, tol, correct = "0", threads = "2", interrogate;
  bool skip_bad = false, quiet = false;
};

// A percentage in (0, 100) as a fraction.
double percent(const std::string& option, const std::string& text) {
  const double p = parse_numbers(option, text, 1, 1)[0];
  if (!(p > 0 && p < 100))
    throw InputError(option + " '" + text + "': expected a percentage in (0, 100)");
  return p / 100.0;
}

void run(const PatchArgs& a) {
  PatchJobOptions o;
  if (!a.boundary.empty()) o.boundary_file = a.boundary;
  if (!a.grid.empty()) {
    const std::vector<double> g = parse_numbers("--grid", a.grid, 2, 2);
    for (const double x : g)
      if (!(x >= 3 && x <= 1e7 && x == std::floor(x)))
        throw InputError("--grid '" + a.grid + "': expected ROWS,COLS, whole numbers >= 3");
    o.grid = {static_cast<int>(g[0]), static_cast<int>(g[1])};
  }
  PatchFitOptions& f = o.fit;
  constexpr BaseKind kinds[] = {BaseKind::bilinear, BaseKind::bicubic, BaseKind::tensor};
  f.base.kind = kinds[parse_choice("--base", a.base, {"bilinear", "bicubic", "tensor"})];
  if (!a.base_share.empty()) f.base.share = percent("--base-share", a.base_share);
  if (!a.base_ctrl.empty())
    std::tie(f.base.control_u, f.base.control_v) =
        parse_int_pair("--base-ctrl", a.base_ctrl, 2, 500);
  if (!a.base_degree.empty())
    std::tie(f.base.degree_u, f.base.degree_v) =
        parse_int_pair("--base-degree", a.base_degree, 1, 9);
  constexpr CrossScale scales[] = {CrossScale::automatic, CrossScale::yes, CrossScale::no};
  f.base.cross_scale = scales[parse_choice("--cross-scale", a.cross_scale, {"auto", "yes", "no"})];
  if (!a.decomposition_tol.empty())
    f.decomposition.tolerance_rel = percent("--decomposition-tol", a.decomposition_tol);
  f.decomposition.split = parse_choice("--split", a.split, {"extent", "curvature"}) == 0
                              ? SplitRule::extent
                              : SplitRule::curvature;
  f.search.search = parse_choice("--search", a.search, {"grid3d", "plane"}) == 0
                        ? PatchSearch::grid3d
                        : PatchSearch::plane;
  f.search.polish = parse_choice("--polish", a.polish, {"yes", "no"}) == 0;
  if (!a.thin.empty()) f.thin = percent("--thin", a.thin);
  std::tie(f.degree_u, f.degree_v) = parse_int_pair("--degree", a.degree, 1, 9);
  if (!a.ctrl.empty() && !a.tol.empty()) throw InputError("give --ctrl or --tol, not both");
  if (!a.ctrl.empty())
    std::tie(f.control_u, f.control_v) = parse_int_pair("--ctrl", a.ctrl, 2, 500);
  if (!a.tol.empty()) {
    f.tolerance = parse_numbers("--tol", a.tol, 1, 1)[0];
    if (!(f.tolerance > 0)) throw InputError("--tol '" + a.tol + "': expected a positive length");
  }
  f.correction_rounds = parse_int_pair("--correct", a.correct, 0, 100).first;
  f.threads = parse_int_pair("--threads", a.threads, 1, 256).first;
  o.interrogate = interrogate_option(a.interrogate);
  o.skip_bad = a.skip_bad;
  ProgressBar bar("fitting ", !a.quiet);
  f.progress = std::ref(bar);
  const PatchJobResult r = run_patch_job(a.scan, o);
  bar.finish();
  const std::vector<std::string> files = write_patch_outputs(r, a.out);
  const PatchFit& p = r.patch;
  if (!a.quiet) {
    std::printf("%s: %ld points, boundary from the %s\n", r.input.filename().string().c_str(),
                static_cast<long>(r.points.cols()), r.boundary_source.c_str());
    std::printf("base %s (%d x %d): max distance %.4g mm; %d quads, %d clamped\n",
                base_kind_name(p.base.kind).c_str(), p.base.surface.size_u(),
                p.base.surface.size_v(), p.base.max_distance, p.decomposition.blanket.quads(),
                p.parameters.stats.clamped_points);
    if (p.net)
      std::printf("net %d x %d chosen by GCV from %zu candidates: %s; noise %.4g mm\n",
                  p.net->control_u, p.net->control_v, p.net->candidates.size(),
                  p.net->stop.c_str(), p.net->noise);
    std::printf(
        "surface %d x %d, degree (%d, %d); distance of all points rms %.4g, p95 %.4g, max "
        "%.4g mm\n",
        p.fit.surface.size_u(), p.fit.surface.size_v(), p.fit.surface.degree_u(),
        p.fit.surface.degree_v(), p.error.rms, p.error.p95, p.error.max);
    std::printf("wrote %zu files to %s (%.0f ms)\n", files.size(),
                std::filesystem::absolute(a.out).string().c_str(), r.total_seconds * 1e3);
  }
  if (!a.tol.empty() && !r.tolerance_met())
    throw NumericalError("--tol " + a.tol +
                         " mm not met: the max distance of the fitted points is " +
                         number_text(p.fit.max_distance) + " mm (report in " + a.out + ")");
}

}  // namespace

void add_patch_command(CLI::App& app) {
  auto args = std::make_shared<PatchArgs>();
  CLI::App* cmd = app.add_subcommand(
      "patch",
      "Fit a scanned patch (a handle, a spout, a face region: anything not single-valued about a\n"
      "centre or an axis) by a parametric B-spline surface (Piegl & Tiller 2001): a base surface\n"
      "spanned by the boundary parametrises every point through its crack-free quad blanket, a\n"
      "grid search and Newton; the surface is then fitted with the boundary fixed. SCAN is any\n"
      "file fit reads (xyz/csv, PLY, STL, OBJ, OFF). Writes surface.igs/.stp/.x3d, base.igs/.x3d,\n"
      "decomposition.svg, parameters.csv, thinned.ply (--thin), deviation.ply, preview.svg,\n"
      "report.json and report.html. Exit 1 when --tol is not met (files written), 2 on bad input.");
  cmd->add_option("scan", args->scan, "point cloud or mesh file")->required();
  cmd->add_option("--out", args->out, "output directory (created if missing)")->required();
  cmd->add_option("--boundary", args->boundary,
                  "CSV 'curve,x,y,z': four polylines in loop order (each may run either way)");
  cmd->add_option("--grid", args->grid,
                  "ROWS,COLS: SCAN is a row-major structured grid; its border is the boundary");
  cmd->add_option("--base", args->base,
                  "bilinear|bicubic|tensor: the base surface (default bilinear Coons)");
  cmd->add_option("--base-share", args->base_share,
                  "percent of the points a bicubic/tensor base is fitted to (default 30)");
  cmd->add_option("--base-ctrl", args->base_ctrl, "n,m: tensor base net (default: the boundary's)");
  cmd->add_option("--base-degree", args->base_degree,
                  "p,q: tensor base degrees (default 2, "
                  "at least the boundary's)");
  cmd->add_option("--cross-scale", args->cross_scale,
                  "auto|yes|no: scale the bicubic base's derivatives against overshoot");
  cmd->add_option("--decomposition-tol", args->decomposition_tol,
                  "flatness of the quad blanket, percent of the base net's diagonal (default 0.5)");
  cmd->add_option("--split", args->split, "extent|curvature: how non-flat quads are split");
  cmd->add_option("--search", args->search,
                  "grid3d|plane: nearest quad by a 3D grid (default) or in the max-area plane");
  cmd->add_option("--polish", args->polish, "yes|no: Newton to the exact foot on the base");
  cmd->add_option("--thin", args->thin,
                  "thin the points by the base's geometry at this percent of its diagonal");
  cmd->add_option("--degree", args->degree, "p,q: degrees of the fitted surface (default 3,3)");
  cmd->add_option("--ctrl", args->ctrl,
                  "n,m: control net (default: chosen by GCV, grown from the boundary's)");
  cmd->add_option("--tol", args->tol, "refine the net until every fitted point is this near [mm]");
  cmd->add_option("--correct", args->correct,
                  "parameter-correction rounds (project, refit; the best kept; default 0)");
  add_interrogate_option(*cmd, args->interrogate);
  cmd->add_option("--threads", args->threads, "worker threads (default 2)");
  cmd->add_flag("--skip-bad", args->skip_bad, "drop unreadable records instead of failing");
  cmd->add_flag("--quiet,-q", args->quiet, "no progress bar and no summary");
  cmd->callback([args] { run(*args); });
}

}  // namespace polarform::cli
