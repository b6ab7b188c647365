// `polarform vessel`: synthesise a pressure-vessel head from prescribed curvatures, convert it to
// an exact NURBS profile within the tolerance, revolve it into the head and vessel surfaces,
// compute the membrane stresses and write CAD files, plots and reports.
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "src/error.h"
#include "ui/cli/commands.h"
#include "ui/cli/validators.h"
#include "jobs/vessel/vessel_outputs.h"

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
  const auto& synthesis = report["synthesis"];
  const auto& stresses = report["stresses"];
  const PolarConversion& c = r.converted.conversion;
  const SynthesisResult& s = r.solved.solution.synthesis;
  std::printf("synthesis: %zu targets, %d iterations (%s), max |kappa residual| %.3g 1/mm, "
              "max condition violation %.3g\n",
              s.targets.size(), s.iterations, s.termination.c_str(),
              synthesis["max_abs_residual_per_mm"].get<double>(), s.max_violation);
  std::printf("head depth %.3f mm; NURBS profile: %zu arcs, degree %d, %d control points\n",
              r.solved.solution.depth, c.arcs.size(), c.curve.degree(), c.curve.size());
  std::printf("tolerance %.3g mm: measured max radial error %.3g mm, max normal error %.3g mm\n",
              c.tolerance, c.max_radial_error, c.max_normal_error);
  std::printf("membrane stress: max %.4g MPa; compressive hoop stress: ",
              stresses["max_stress_mpa"].get<double>());
  if (stresses["compressive_hoop"].get<bool>())
    std::printf("YES, down to %.4g MPa\n", stresses["head"]["min_hoop_stress_mpa"].get<double>());
  else
    std::printf("none\n");
  std::printf("wrote %zu files to %s (%.0f ms)\n", files.size(),
              std::filesystem::absolute(a.out).string().c_str(), r.seconds.total * 1e3);
}

}  // namespace

void add_vessel_command(CLI::App& app) {
  auto args = std::make_shared<VesselArgs>();
  CLI::App* cmd = app.add_subcommand(
      "vessel",
      "Design a pressure-vessel head from prescribed curvatures (or a hemispherical,\n"
      "ellipsoidal or torispherical preset) under end conditions, convert it to an exact NURBS\n"
      "profile within the tolerance, revolve it and compute the membrane stresses under the\n"
      "internal pressure. Writes profile.igs/.stp/.dxf, head.igs/.stp, vessel.stp,\n"
      "curvature.svg, stress.svg, profile.svg, profile.csv, stress.csv, report.json and\n"
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
