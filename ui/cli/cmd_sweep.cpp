// `polarform sweep`: recover a swept surface from a scan or mesh of a turned or extruded part
// (Kantz 2003): the axis and meridian profile of a surface of revolution, or the direction and
// section of an extrusion, and the exact surface; or the skin of star-shaped sections along a
// straight or curved spine (--kind sections); with the true distances of every point. Exit 1
// when --tol is not met (the bundle is written, the report says by how much).
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "jobs/project/sweep_project.h"
#include "jobs/sweep/sweep_outputs.h"
#include "src/error.h"
#include "src/number_text.h"
#include "ui/cli/commands.h"
#include "ui/cli/fit_arguments.h"
#include "ui/cli/interrogate_option.h"

namespace polarform::cli {

namespace {

struct SweepArgs {
  // Empty: not given (the project's value, or the default).
  std::string scan, out, kind, axis, center, tol, degree, corner_angle, threads = "2", interrogate,
                                                                        sections, spine;
  bool skip_bad = false, quiet = false, lenient = false;
};

Eigen::Vector3d vector3(const std::string& option, const std::string& text) {
  const std::vector<double> v = parse_numbers(option, text, 3, 3);
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

// The options given on the command line, over `o` (a project's or the defaults).
SweepJobOptions job_options(const SweepArgs& a, SweepJobOptions o) {
  constexpr SweepKind kinds[] = {SweepKind::automatic, SweepKind::revolution, SweepKind::extrusion,
                                 SweepKind::sections};
  if (!a.kind.empty())
    o.kind = kinds[parse_choice("--kind", a.kind, {"auto", "revolution", "extrusion", "sections"})];
  if (!a.sections.empty()) o.sections = parse_int_pair("--sections", a.sections, 2, 1000).first;
  constexpr SpineShape spines[] = {SpineShape::automatic, SpineShape::straight, SpineShape::curved};
  if (!a.spine.empty())
    o.spine = spines[parse_choice("--spine", a.spine, {"auto", "straight", "curved"})];
  if (!a.axis.empty()) o.axis = vector3("--axis", a.axis);
  if (!a.center.empty()) o.center = vector3("--center", a.center);
  if (!a.tol.empty()) {
    o.tolerance = parse_numbers("--tol", a.tol, 1, 1)[0];
    if (!(o.tolerance > 0))
      throw InputError("--tol '" + a.tol + "': expected a positive number of mm");
  }
  if (!a.degree.empty()) o.degree = parse_int_pair("--degree", a.degree, 1, 9).first;
  if (!a.corner_angle.empty()) {
    o.corner_angle_deg = parse_numbers("--corner-angle", a.corner_angle, 1, 1)[0];
    if (!(o.corner_angle_deg > 0 && o.corner_angle_deg < 180))
      throw InputError("--corner-angle '" + a.corner_angle + "': expected degrees in (0, 180)");
  }
  o.threads = parse_int_pair("--threads", a.threads, 1, 256).first;
  o.skip_bad = o.skip_bad || a.skip_bad;
  if (const auto q = interrogate_option(a.interrogate)) o.interrogate = q;
  return o;
}

void run(const SweepArgs& a) {
  // A project file (.xml) names the scan and its options; flags given here override them.
  std::filesystem::path scan = a.scan;
  SweepJobOptions defaults;
  if (std::filesystem::path(a.scan).extension() == ".xml") {
    std::vector<std::string> warnings;
    const SweepProject project =
        read_sweep_project(a.scan, warnings, unknown_names_policy(a.lenient));
    for (const std::string& w : warnings) std::cerr << "polarform: warning: " << w << "\n";
    scan = scan_path(project, a.scan);
    defaults = sweep_job_options(project);
  }
  const SweepJobOptions o = job_options(a, defaults);
  const SweepJobResult r = run_sweep_job(scan, o);
  const std::vector<std::string> files = write_sweep_outputs(r, a.out);
  const SweptFit& v = r.fit();
  if (!a.quiet) {
    if (r.is_sections) {
      std::printf("%s: %ld points, %zu sections skinned along a %s spine of %.9g mm\n",
                  r.input.filename().string().c_str(), static_cast<long>(r.points.cols()),
                  r.sections->stations.size(), r.sections->spine_curved ? "curved" : "straight",
                  r.sections->spine_length);
    } else if (r.is_extrusion) {
      const Eigen::Vector3d& d = r.extrusion->direction;
      std::printf("%s: %ld points, extrusion along (%.9g, %.9g, %.9g), length %.9g mm\n",
                  r.input.filename().string().c_str(), static_cast<long>(r.points.cols()), d.x(),
                  d.y(), d.z(), r.extrusion->length());
    } else {
      const AxisLine& x = r.revolution->axis;
      std::printf(
          "%s: %ld points, surface of revolution, axis through (%.9g, %.9g, %.9g) along (%.9g, "
          "%.9g, %.9g)\n",
          r.input.filename().string().c_str(), static_cast<long>(r.points.cols()), x.point.x(),
          x.point.y(), x.point.z(), x.direction.x(), x.direction.y(), x.direction.z());
    }
    std::printf(
        "%zu %s loop(s), surface degree (%d, %d); distance of all points rms %.4g, p95 %.4g, "
        "max %.4g mm\n",
        v.profile.loops.size(), r.is_extrusion || r.is_sections ? "section" : "profile",
        v.surfaces.empty() ? 0 : v.surfaces[0].degree_u(),
        v.surfaces.empty() ? 0 : v.surfaces[0].degree_v(), v.error.rms, v.error.p95, v.error.max);
    std::printf("wrote %zu files to %s (%.0f ms)\n", files.size(),
                std::filesystem::absolute(a.out).string().c_str(), r.total_seconds * 1e3);
  }
  if (o.tolerance > 0 && !r.tolerance_met())
    throw NumericalError("--tol " + number_text(o.tolerance) + " mm not met: the max distance is " +
                         number_text(v.error.max) + " mm (" + std::to_string(v.unexplained) +
                         " points farther; report in " + a.out + ")");
}

}  // namespace

void add_sweep_command(CLI::App& app) {
  auto args = std::make_shared<SweepArgs>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Recover the exact swept surface of a scanned or meshed part (Kantz 2003). A turned part:\n"
      "the axis (PCA, refined by Gauss-Newton on ring clusters or profile residuals), every point\n"
      "projected to the meridian plane, the profile fitted to a tolerance with corners and poles,\n"
      "revolved exactly (degree (2, p)). An extruded part: the direction (local normals, refined\n"
      "against the section), every point projected onto the section plane, the section fitted\n"
      "(polar fit when star-shaped), extruded exactly (degree (p, 1)). --kind auto decides by the\n"
      "normals (flat: extrusion; in planes through the axis: revolution; else both, the better\n"
      "kept). --kind sections (never chosen by auto): sections sliced perpendicular to a spine\n"
      "(the PCA axis, bent through the section centres until it moves less than the tolerance),\n"
      "each fitted as a closed star-shaped polar curve on one base circle and knot vector, "
      "skinned\n"
      "(NURBS Book 10.3), stations added where the skin misses the points (adaptive slicing).\n"
      "SCAN is any file fit reads (xyz/csv, PLY, STL, OBJ, OFF).\n"
      "Writes surface.igs/.stp/.x3d, profile.igs/.stp/.dxf/.svg (sections: sections.igs/.svg),\n"
      "solid.stp (an extrusion of one closed section), deviation.ply, preview.svg, report.json\n"
      "and report.html.\n"
      "Exit 1 when --tol is not met (files written), 2 on bad input.");
  cmd->add_option("scan", args->scan,
                  "point cloud or mesh file, or a sweep project (.xml, see docs/file-formats.md) "
                  "naming one")
      ->required();
  cmd->add_option("--out", args->out, "output directory (created if missing)")->required();
  cmd->add_option("--kind", args->kind, "auto|revolution|extrusion|sections (default auto)");
  cmd->add_option("--axis", args->axis,
                  "X,Y,Z: the axis or extrusion direction to start from (default: PCA or the "
                  "normals; refined either way)");
  cmd->add_option("--center", args->center, "X,Y,Z: a point on the axis (with --axis)");
  cmd->add_option("--tol", args->tol,
                  "max distance of every point to the surface [mm] (default 1e-4 of the size)");
  cmd->add_option("--degree", args->degree, "profile degree p (default 3)");
  cmd->add_option("--corner-angle", args->corner_angle,
                  "turning angle of a profile corner [deg] (default 30)");
  cmd->add_option("--sections", args->sections,
                  "--kind sections: exactly N sections (default: adaptive slicing)");
  cmd->add_option("--spine", args->spine,
                  "--kind sections: auto|straight|curved (default auto: straight unless the "
                  "section centres leave the PCA axis by more than the tolerance)");
  add_interrogate_option(*cmd, args->interrogate);
  cmd->add_option("--threads", args->threads, "worker threads (default 2)");
  cmd->add_flag("--skip-bad", args->skip_bad, "drop unreadable records instead of failing");
  cmd->add_flag("--quiet,-q", args->quiet, "print nothing but errors");
  cmd->add_flag("--lenient", args->lenient, kLenientHelp);
  cmd->callback([args] { run(*args); });
}

}  // namespace polarform::cli
