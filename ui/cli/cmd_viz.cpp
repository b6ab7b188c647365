// `polarform viz`: show a grid of values measured on a spherical or cylindrical set-up as a NURBS
// surface whose radius is the value (Bae 2002, §5.3, eq. (5.6)), coloured by the value.
#include <cstdio>
#include <filesystem>

#include "src/error.h"
#include "ui/cli/commands.h"
#include "ui/cli/fit_arguments.h"
#include "jobs/viz/viz_outputs.h"

namespace polarform::cli {

namespace {

struct VizArgs {
  std::string grid, out, degree, ctrl, scale, offset, closed = "auto", threads = "2";
  bool quiet = false;
};

void run(const VizArgs& a) {
  VizJobOptions o;
  if (!a.degree.empty()) o.degree = parse_int_pair("--degree", a.degree, 1, 9);
  if (!a.ctrl.empty()) o.ctrl = parse_int_pair("--ctrl", a.ctrl, 2, 2000);
  if (!a.scale.empty()) o.scale = parse_numbers("--scale", a.scale, 1, 1)[0];
  if (!a.offset.empty()) o.offset = parse_numbers("--offset", a.offset, 1, 1)[0];
  constexpr Closure closures[] = {Closure::automatic, Closure::closed, Closure::open};
  o.closure = closures[parse_choice("--closed", a.closed, {"auto", "yes", "no"})];
  o.threads = parse_int_pair("--threads", a.threads, 1, 256).first;
  const VizJobResult r = run_viz_job(a.grid, o);
  const std::vector<std::string> files = write_viz_outputs(r, a.out);
  if (a.quiet) return;
  const ScalarFieldSurface& f = r.field;
  std::printf("%s set-up, %ld values of '%s' in [%.6g, %.6g]: S = (%.6g·F + %.6g)·B\n",
              r.grid.setup == GridSetup::spherical ? "spherical" : "cylindrical",
              static_cast<long>(r.grid.value.size()), r.grid.value_name.c_str(),
              r.grid.value.minCoeff(), r.grid.value.maxCoeff(), r.scale, r.offset);
  std::printf(
      "F degree (%d, %d), %d x %d control values; NURBS degree (%d, %d); |F - p| rms %.4g, max "
      "%.4g\n",
      f.F.degree_u(), f.F.degree_v(), f.F.size_u(), f.F.size_v(), f.surface.degree_u(),
      f.surface.degree_v(), f.fit_error.rms, f.fit_error.max);
  std::printf("wrote %zu files to %s (%.0f ms)\n", files.size(),
              std::filesystem::absolute(a.out).string().c_str(), r.seconds * 1e3);
}

}  // namespace

void add_viz_command(CLI::App& app) {
  auto args = std::make_shared<VizArgs>();
  CLI::App* cmd = app.add_subcommand(
      "viz",
      "Visualise values measured on a spherical or cylindrical set-up (Bae 2002, §5.3) as the "
      "NURBS\n"
      "surface S = (s·F + d)·B whose radius is the value. GRID is delimited text whose first line "
      "names\n"
      "the columns: p,phi_deg,theta_deg (spherical) or p,theta_deg,z_mm (cylindrical), the value "
      "under\n"
      "any name other than these; angles in degrees, z in mm, '#' starts a comment. Writes "
      "surface.igs,\n"
      "surface.stp, surface.x3d (coloured by the value, per vertex and per control point),\n"
      "control_values.csv, preview.svg, report.json and report.html.");
  cmd->add_option("grid", args->grid, "grid file (see above)")->required();
  cmd->add_option("--out", args->out, "output directory (created if missing)")->required();
  cmd->add_option("--degree", args->degree, "p[,q]: degrees of F along φ or z, and θ (default 3)");
  cmd->add_option("--ctrl", args->ctrl, "n[,m]: control values of F (default 12)");
  cmd->add_option("--scale", args->scale, "s of S = (s·F + d)·B (default 1)");
  cmd->add_option("--offset", args->offset,
                  "d of S = (s·F + d)·B (default 0, or a shift that keeps radii positive)");
  cmd->add_option("--closed", args->closed, "auto|yes|no: close the surface around the axis");
  cmd->add_option("--threads", args->threads, "worker threads (default 2)");
  cmd->add_flag("--quiet,-q", args->quiet, "print nothing but errors");
  cmd->callback([args] { run(*args); });
}

}  // namespace polarform::cli
