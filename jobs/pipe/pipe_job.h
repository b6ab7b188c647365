// The pipe job of `polarform pipe` (Patrikalakis & Maekawa, MIT 13.472J §8.3–8.4): a spine read
// from points (interpolated by a cubic spline with knots at their chord lengths) or given as a
// NURBS (a <pipe> project, jobs/project/pipe_project.h), the local and
// global self-intersection bounds of a pipe around it, and — when the radius is below them, or
// when allowed anyway — the pipe surface as NURBS within a tolerance. Computing writes nothing;
// pipe_outputs.h writes the bundle.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "src/nurbs/pipe_self_intersection.h"
#include "src/nurbs/pipe_surface.h"

namespace polarform {

enum class SpineClosure { automatic, closed, open };

struct PipeJobOptions {
  double radius = 0.0;  // mm, > 0
  FrameRule frame = FrameRule::rmf;
  double tolerance = 0.0;  // mm; <= 0: 1e-4 of the spine's size
  SpineClosure closure = SpineClosure::automatic;
  bool allow_self_intersection = false;
};

struct PipeJobResult {
  std::filesystem::path input;
  double radius = 0.0;
  FrameRule frame = FrameRule::rmf;
  Eigen::Matrix3Xd points;  // the spine points as read (a NURBS spine: its control points)
  NurbsCurve3d spine;       // through them, parameter = chord length (mm); or as given
  bool chord_length_parameter = true;  // false for a NURBS spine: t is its own parameter
  bool closed = false;
  double length = 0.0;  // mm, the spine's arc length
  SpineCurvature curvature;
  PipeBounds bounds;
  bool nonsingular = true;  // radius < bounds.delta
  double tolerance = 0.0;
  PipeSurface pipe;
  std::vector<std::string> warnings;
  double seconds = 0.0;
};

// The cubic spline through the points at chord-length parameters: open, its end tangents those of
// the parabolas through the first and last three points (Bessel; two points: a line); closed (the
// last point repeats the first), both ends get the same tangent, so the spine is C1 at the seam.
NurbsCurve3d spine_through(const Eigen::Matrix3Xd& points, bool closed);

// Throws InputError for a bad file or options, and for a radius at or beyond the bound δ (an
// infeasible design: the message names the limiting mode, δ and where) unless
// allow_self_intersection, which records a warning instead.
PipeJobResult run_pipe_job(const std::filesystem::path& spine_file, const PipeJobOptions& options);

// As above for a spine given as a NURBS curve (`input` names it in messages and the report):
// closed when options.closure says so, or — automatic — when its ends meet to 1e-9 of its
// control net's size; a closed spine whose ends do not meet is refused.
PipeJobResult run_pipe_job(const std::filesystem::path& input, const NurbsCurve3d& spine,
                           const PipeJobOptions& options);

}  // namespace polarform
