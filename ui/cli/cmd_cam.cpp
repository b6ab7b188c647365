// `polarform cam`: design a cam from a project file, convert its profile to an exact NURBS curve
// within the tolerance and write CAD files, plots and reports.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <numbers>

#include "jobs/cam/cam_key_figures.h"
#include "jobs/cam/cam_outputs.h"
#include "src/units.h"
#include "ui/cli/commands.h"
#include "ui/cli/validators.h"

namespace polarform::cli {

namespace {

struct CamArgs {
  std::string design;
  std::string out;
  std::optional<double> tolerance;
  std::string base;
  std::optional<int> max_degree;
  std::optional<double> solid;
  std::optional<double> bore;
  bool quiet = false;
  bool lenient = false;
};

// An infeasible design's analyses, written where they alter no earlier run's outputs; what the
// error message adds about them.
std::string written_analyses(const InfeasibleCam& cam, const std::string& out,
                             const CamOutputOptions& options) {
  const std::filesystem::path dir = infeasible_outputs_dir(out);
  try {
    write_infeasible_cam_outputs(cam, dir, options);
  } catch (const std::exception& e) {
    return " (its analyses could not be written: " + std::string(e.what()) + ")";
  }
  return "; no profile written; the analyses of the infeasible design, undercut shaded, are in " +
         std::filesystem::absolute(dir).string() + " (report.html, analysis.svg)";
}

void run(const CamArgs& a) {
  std::vector<std::string> warnings;
  CamProject project = read_cam_project(a.design, warnings, unknown_names_policy(a.lenient));
  for (const std::string& w : warnings) std::cerr << "polarform: warning: " << w << "\n";
  if (a.tolerance) project.conversion.tolerance = *a.tolerance;
  if (!a.base.empty()) project.conversion.base = a.base == "rqb" ? ArcKind::rqb : ArcKind::quartic;
  if (a.max_degree) project.max_degree = *a.max_degree;

  CamOutputOptions options;
  options.design_name = std::filesystem::path(a.design).stem().string();
  options.solid_thickness = a.solid;
  options.bore_diameter = a.bore;
  const CamJobResult r = for_design(a.design, [&] {
    try {
      return run_cam_job(project);
    } catch (const InfeasibleCamError& e) {
      throw InputError(std::string(e.what()) + written_analyses(e.cam(), a.out, options));
    }
  });
  const std::vector<std::string> files = write_cam_outputs(r, a.out, options);

  for (const auto* list : {&r.analysis.warnings, &r.conversion.warnings})
    for (const std::string& w : *list) std::cerr << "polarform: warning: " << w << "\n";
  for (const ContinuityIssue& issue : r.design.continuity)
    std::cerr << "polarform: motion: " << issue.message() << "\n";
  if (a.quiet) return;
  const PolarConversion& c = r.conversion.conversion;
  const std::vector<KeyFigure> inputs = cam_design_inputs(r.design);
  const std::vector<KeyFigure> results = cam_key_results(r.design, r.analysis, &r.conversion);
  std::printf("%s cam, %s follower: %zu arcs, degree %d, %d control points\n",
              std::string(cam_type_name(project.cam.type)).c_str(),
              std::string(follower_kind_name(project.cam.follower.kind)).c_str(), c.arcs.size(),
              r.conversion.degree(), r.conversion.control_points());
  // The design and the key results, as report.html's first tables state them.
  for (const auto* figures : {&inputs, &results})
    for (const KeyFigure& f : *figures) std::printf("%s: %s\n", f.name.c_str(), f.value.c_str());
  if (const auto* p = std::get_if<PlateProfile>(&r.conversion.profile); p && p->limited)
    std::printf("degree-%d profile: %d control points, measured max radial error %.3g mm\n",
                p->limited->curve.degree(), p->limited->control_points,
                p->limited->max_radial_error);
  if (const auto* t = std::get_if<CylindricalTrack>(&r.conversion.profile))
    for (const GrooveSurface& g : t->groove)
      std::printf(
          "groove wall %s: degree %d x %d, %d x %d control points, "
          "measured max error %.3g mm\n",
          g.side > 0 ? "+z" : "-z", g.surface.degree_u(), g.surface.degree_v(), g.surface.size_u(),
          g.surface.size_v(), g.max_error);
  std::printf("wrote %zu files to %s (%.0f ms)\n", files.size(),
              std::filesystem::absolute(a.out).string().c_str(), r.seconds * 1e3);
}

}  // namespace

void add_cam_command(CLI::App& app) {
  auto args = std::make_shared<CamArgs>();
  CLI::App* cmd = app.add_subcommand(
      "cam",
      "Design a plate or cylindrical cam from a project file and export its exact NURBS profile.\n"
      "Writes profile.igs/.stp/.dxf/.x3d (track.* for cylindrical cams), profile_deg3.dxf,\n"
      "svaj.csv, svaj.svg, analysis.svg, profile.svg, error.svg, report.json and report.html;\n"
      "groove_plate.igs/.stp/.dxf for a grooved plate cam, conjugate.igs/.stp/.dxf for a\n"
      "conjugate one.\n"
      "An undercut design exits 2 and writes only its analyses (svaj.*, analysis.svg, reports\n"
      "marked infeasible), into --out if it is empty, else into OUT.infeasible beside it.");
  cmd->add_option("design", args->design, "cam project file (XML, see docs/file-formats.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", args->out, "output directory (created if missing)")->required();
  cmd->add_option("--tol", args->tolerance, "conversion tolerance in mm (overrides the project)")
      ->check(tolerance_mm());
  cmd->add_option("--base", args->base, "base-circle arcs (overrides the project)")
      ->check(CLI::IsMember({"quasi-uniform", "rqb"}));
  cmd->add_option("--max-degree", args->max_degree,
                  "cap the degree of the exported profile (approximated within the tolerance)")
      ->check(CLI::Range(1, 40));
  auto* solid = cmd->add_option("--solid", args->solid,
                                "also write the plate cam as a solid of this thickness in mm "
                                "(cam_solid.stp; a grooved cam's plate with its groove; "
                                "conjugate_solid.stp for a conjugate cam's second cam)")
                    ->check(positive_mm());
  cmd->add_option("--bore", args->bore, "bore diameter of the solid in mm")
      ->check(positive_mm())
      ->needs(solid);
  cmd->add_flag("--quiet,-q", args->quiet, "print nothing but warnings and errors");
  cmd->add_flag("--lenient", args->lenient, kLenientHelp);
  cmd->callback([args] { run(*args); });
}

}  // namespace polarform::cli
