// `polarform vessel`: synthesise a pressure-vessel head from prescribed curvatures, convert it to
// an exact NURBS profile within the tolerance, revolve it into the head and vessel surfaces,
// compute the membrane stresses and write CAD files, plots and reports.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "jobs/vessel/vessel_outputs.h"
#include "src/error.h"
#include "src/units.h"
#include "ui/cli/commands.h"
#include "ui/cli/validators.h"

namespace polarform::cli {

namespace {

struct VesselArgs {
  std::string design;
  std::string out;
  std::optional<double> tolerance;
  bool quiet = false;
  bool lenient = false;
};

// The job's errors name the field and the numbers; the file they came from is added here.
VesselJobResult run_job(const VesselProject& project, const std::string& file) {
  try {
    return run_vessel_job(project);
  } catch (const InputError& e) {
    throw InputError(file + ": " + e.what());
  } catch (const NumericalError& e) {
    throw NumericalError(file + ": " + e.what());
  }
}

void run(const VesselArgs& a) {
  std::vector<std::string> warnings;
  VesselProject project = read_vessel_project(a.design, warnings, unknown_names_policy(a.lenient));
  for (const std::string& w : warnings) std::cerr << "polarform: warning: " << w << "\n";
  if (a.tolerance) project.tolerance = *a.tolerance;

  const VesselJobResult r = run_job(project, a.design);
  VesselOutputOptions options;
  options.design_name = std::filesystem::path(a.design).stem().string();
  const std::vector<std::string> files = write_vessel_outputs(r, a.out, options);

  for (const std::string& w : r.solved.solution.warnings)
    std::cerr << "polarform: vessel: " << w << "\n";
  if (a.quiet) return;
  // The figures as the report states them.
  const nlohmann::ordered_json report = vessel_report_json(r, files);
  const auto& stresses = report["stresses"];
  const VesselSolution& solution = r.solved.solution;
  const VesselConversionStage& c = r.converted;
  if (solution.exact) {
    std::printf("head: %s, exact (rational quadratic arcs)\n", solution.exact->shape.name.c_str());
  } else if (const auto& m = solution.minimum_stress) {
    std::printf("minimum-stress head: peak membrane stress %.5g MPa (%d iterations, %s)\n",
                m->stresses.peak_stress, m->head.iterations, m->head.termination.c_str());
    for (const HeadStressSummary& h : m->same_depth.references)
      std::printf("  same depth: %s: peak %.5g MPa\n", h.name.c_str(), h.peak_stress);
    std::printf("  %.3g %% below the best standard head of its depth\n",
                report["minimum_stress"]["peak_below_best_standard_pct"].get<double>());
  } else {
    const SynthesisResult& s = solution.synthesis;
    std::printf(
        "synthesis: %zu targets, %d iterations (%s), max |kappa residual| %.3g 1/mm, "
        "max condition violation %.3g\n",
        s.targets.size(), s.iterations, s.termination.c_str(),
        report["synthesis"]["max_abs_residual_per_mm"].get<double>(), s.max_violation);
    const SmoothingChoice& choice = solution.smoothing;
    if (choice.rule != SmoothingRule::fixed)
      std::printf("smoothing: %s, lambda %.3g chosen in %d trials%s\n",
                  smoothing_rule_name(choice.rule), s.smoothing, choice.trials,
                  choice.met ? "" : " (no weight met the rule; the closest is used)");
  }
  std::printf("head depth %.3f mm; NURBS profile: %d arcs, degree %d, %d control points\n",
              solution.depth, c.arcs, c.profile.degree(), c.profile.size());
  if (c.conversion)
    std::printf("tolerance %.3g mm: measured max radial error %.3g mm, max normal error %.3g mm\n",
                c.conversion->tolerance, c.max_radial_error, c.conversion->max_normal_error);
  else
    std::printf("measured max radial error against the closed form %.3g mm\n", c.max_radial_error);
  std::printf("membrane stress: max %.4g MPa; compressive hoop stress: ",
              stresses["max_stress_mpa"].get<double>());
  if (stresses["compressive_hoop"].get<bool>())
    std::printf("YES, down to %.4g MPa\n", stresses["head"]["min_hoop_stress_mpa"].get<double>());
  else
    std::printf("none\n");
  for (const EdgeBending& e : solution.edge_bending)
    std::printf(
        "edge bending at theta %.4g deg: meridional %.4g MPa (bending %.4g of it), "
        "hoop %.4g MPa at the joint%s\n",
        to_degrees(e.theta), e.max_meridional_stress, e.bending_stress, e.hoop_stress_at_joint,
        e.approximate() ? " (approximate: short piece)" : "");
  if (const auto& code = solution.code) {
    std::printf("ASME VIII-1: MAWP %.4g MPa; required thickness shell %.4g mm (%s)", code->mawp,
                code->shell.required_thickness, code->shell.thickness_formula.c_str());
    if (code->head)
      std::printf(", head %.4g mm (%s)", code->head->required_thickness,
                  code->head->thickness_formula.c_str());
    std::printf("; wall %s\n", code->thickness_sufficient ? "sufficient" : "TOO THIN");
  }
  if (const auto& m = solution.measures)
    std::printf(
        "volume %.6g L, metal weight %.5g kg (%.5g kg/m3); one head %.5g kg (straight flange "
        "%.4g mm)\n",
        m->vessel_volume * 1e-6, m->weight, m->density, m->head_weight, m->straight_flange);
  std::printf("wrote %zu files to %s (%.0f ms)\n", files.size(),
              std::filesystem::absolute(a.out).string().c_str(), r.seconds.total * 1e3);
}

}  // namespace

void add_vessel_command(CLI::App& app) {
  auto args = std::make_shared<VesselArgs>();
  CLI::App* cmd = app.add_subcommand(
      "vessel",
      "Design a pressure-vessel head: a standard head (hemispherical, ellipsoidal,\n"
      "torispherical, conical or flanged flat) exactly, as rational quadratic arcs, a head "
      "synthesised from "
      "prescribed\n"
      "curvatures under end conditions, or the head of a given depth with the smallest peak\n"
      "membrane stress (compared with the standard heads of that depth), converted to an exact\n"
      "NURBS profile within the tolerance; revolve it and compute the membrane stresses under the "
      "internal pressure. Writes "
      "profile.igs/.stp/.dxf, head.igs/.stp, vessel.stp,\n"
      "curvature.svg, stress.svg, profile.svg (same_depth.svg), profile.csv, stress.csv, "
      "report.json and\n"
      "report.html (docs/cli-vessel.md).\n"
      "Exit code 2: bad input (file, field or infeasible design); 1: the synthesis did not\n"
      "converge.");
  cmd->add_option("design", args->design, "vessel project file (XML, see docs/cli-vessel.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", args->out, "output directory (created if missing)")->required();
  cmd->add_option("--tol", args->tolerance, "conversion tolerance in mm (overrides the project)")
      ->check(tolerance_mm());
  cmd->add_flag("--quiet,-q", args->quiet, "print nothing but warnings and errors");
  cmd->add_flag("--lenient", args->lenient, kLenientHelp);
  cmd->callback([args] { run(*args); });
}

}  // namespace polarform::cli
