// `polarform pipe`: a pipe of radius r around a spine (Patrikalakis & Maekawa, MIT 13.472J
// §8.3-8.4) — the spine interpolated through the points of SPINE.csv or the NURBS of a SPINE.xml
// <pipe> project, its curvature, the local and global self-intersection bounds, and the pipe
// surface as NURBS within a tolerance. A radius at or beyond the bound is an infeasible design
// (exit 2) unless --allow-self-intersection. Options on the command line win over the project's.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "jobs/pipe/pipe_outputs.h"
#include "jobs/project/pipe_project.h"
#include "src/error.h"
#include "ui/cli/commands.h"
#include "ui/cli/fit_arguments.h"

namespace polarform::cli {

namespace {

struct PipeArgs {
  std::string spine, out, radius, frame, tol, closed;
  bool allow = false, quiet = false, lenient = false;
};

// The command line's options over `o` (a project's, or the defaults).
void apply_arguments(const PipeArgs& a, PipeJobOptions& o) {
  if (!a.radius.empty()) {
    o.radius = parse_numbers("--radius", a.radius, 1, 1)[0];
    if (!(o.radius > 0))
      throw InputError("--radius '" + a.radius + "': expected a positive length");
  }
  if (!(o.radius > 0))
    throw InputError("--radius: required (SPINE.xml may give it as radius=\"mm\")");
  constexpr FrameRule frames[] = {FrameRule::rmf, FrameRule::frenet, FrameRule::fixed};
  if (!a.frame.empty())
    o.frame = frames[parse_choice("--frame", a.frame, {"rmf", "frenet", "fixed"})];
  if (!a.tol.empty()) {
    o.tolerance = parse_numbers("--tol", a.tol, 1, 1)[0];
    if (!(o.tolerance > 0)) throw InputError("--tol '" + a.tol + "': expected a positive length");
  }
  constexpr SpineClosure closures[] = {SpineClosure::automatic, SpineClosure::closed,
                                       SpineClosure::open};
  if (!a.closed.empty())
    o.closure = closures[parse_choice("--closed", a.closed, {"auto", "yes", "no"})];
  o.allow_self_intersection = a.allow;
}

void run(const PipeArgs& a) {
  std::vector<std::string> warnings;
  PipeJobResult r;
  if (std::filesystem::path(a.spine).extension() == ".xml") {
    const PipeProject project =
        read_pipe_project(a.spine, warnings, unknown_names_policy(a.lenient));
    PipeJobOptions o = pipe_job_options(project);
    apply_arguments(a, o);
    r = run_pipe_job(a.spine, pipe_spine(project), o);
  } else {
    PipeJobOptions o;
    apply_arguments(a, o);
    r = run_pipe_job(a.spine, o);
  }
  const std::vector<std::string> files = write_pipe_outputs(r, a.out);
  warnings.insert(warnings.end(), r.warnings.begin(), r.warnings.end());
  for (const std::string& w : warnings) std::cerr << "polarform: warning: " << w << "\n";
  if (!a.quiet) {
    const PipeBounds& b = r.bounds;
    std::printf("%s: %ld %s, %s spine %.6g mm long, κ_max %.6g 1/mm\n",
                r.input.filename().string().c_str(), static_cast<long>(r.points.cols()),
                r.chord_length_parameter ? "points" : "control points",
                r.closed ? "closed" : "open", r.length, r.curvature.kappa_max);
    std::printf(
        "radius bound δ = %.6g mm (%s); local %.6g, end-end %.6g, body-body %.6g, "
        "end-body %.6g mm\n",
        b.delta, b.limiting_mode.c_str(), b.local, b.end_end, b.body_body, b.end_body);
    std::printf("pipe r = %.6g mm: %s surface (%d x %d), max error %.3g mm\n", r.radius,
                r.pipe.exact ? "exact" : "approximate", r.pipe.surface.size_u(),
                r.pipe.surface.size_v(), r.pipe.max_error);
    std::printf("wrote %zu files to %s\n", files.size(),
                std::filesystem::absolute(a.out).string().c_str());
  }
}

}  // namespace

void add_pipe_command(CLI::App& app) {
  auto args = std::make_shared<PipeArgs>();
  CLI::App* cmd = app.add_subcommand(
      "pipe",
      "A pipe of radius r around a spine (MIT 13.472J §8.3-8.4): SPINE.csv ('x,y,z' points in\n"
      "order) is interpolated by a cubic spline, SPINE.xml is a <pipe> project with the spine's\n"
      "control points, weights, degree and knots (docs/file-formats.md); its options there are\n"
      "overridden by the command line's. The spine's curvature, the local bound 1/κ_max and the\n"
      "global bounds (end-end, body-body, end-body) give δ, and a radius at or beyond δ is an\n"
      "infeasible design (exit 2) unless --allow-self-intersection. Writes pipe.igs/.stp/.x3d,\n"
      "spine.igs, curvature.svg, report.json and report.html.");
  cmd->add_option("spine", args->spine, "spine points (CSV 'x,y,z') or a <pipe> project (.xml)")
      ->required();
  cmd->add_option("--radius", args->radius,
                  "pipe radius [mm] (required unless SPINE.xml gives it)");
  cmd->add_option("--out", args->out, "output directory (created if missing)")->required();
  cmd->add_option("--frame", args->frame,
                  "rmf|frenet|fixed: the frame the circles are placed in (default rmf)");
  cmd->add_option("--tol", args->tol,
                  "max deviation of the NURBS from the exact pipe [mm] (default 1e-4 of the size)");
  cmd->add_option("--closed", args->closed,
                  "auto|yes|no: the spine is a closed loop (default auto)");
  cmd->add_flag("--allow-self-intersection", args->allow,
                "write a self-intersecting pipe anyway (a warning, nonsingular: false)");
  cmd->add_flag("--quiet,-q", args->quiet, "print nothing but errors");
  cmd->add_flag("--lenient", args->lenient, kLenientHelp);
  cmd->callback([args] { run(*args); });
}

}  // namespace polarform::cli
