#include "jobs/pipe/pipe_job.h"

#include <chrono>
#include <cmath>
#include <limits>

#include "src/error.h"
#include "src/io/spine_csv.h"
#include "src/number_text.h"
#include "src/nurbs/curve_interpolation.h"
#include "src/nurbs/spine_table.h"

namespace polarform {

NurbsCurve3d spine_through(const Eigen::Matrix3Xd& p, bool closed) {
  const Eigen::Index n = p.cols();
  Eigen::VectorXd t(n);
  t[0] = 0.0;
  for (Eigen::Index k = 1; k < n; ++k) t[k] = t[k - 1] + (p.col(k) - p.col(k - 1)).norm();
  CubicEnds ends;
  if (closed && n >= 3) {
    // The chord through the seam's neighbours, per unit of chord length: one tangent at both ends.
    const Eigen::Vector3d d = (p.col(1) - p.col(n - 2)) / (t[1] + t[n - 1] - t[n - 2]);
    ends.start_tangent = d;
    ends.end_tangent = d;
  } else if (n >= 3) {
    // Bessel ends: the tangents of the parabolas through the first and the last three points
    // (natural ends would straighten the spine there and overshoot its curvature nearby).
    const auto slope = [&](Eigen::Index a, Eigen::Index b) -> Eigen::Vector3d {
      return (p.col(b) - p.col(a)) / (t[b] - t[a]);
    };
    const Eigen::Vector3d s01 = slope(0, 1), s12 = slope(1, 2);
    ends.start_tangent = Eigen::Vector3d(s01 - (t[1] - t[0]) * (s12 - s01) / (t[2] - t[0]));
    const Eigen::Vector3d a = slope(n - 3, n - 2), b = slope(n - 2, n - 1);
    ends.end_tangent = Eigen::Vector3d(b + (t[n - 1] - t[n - 2]) * (b - a) / (t[n - 1] - t[n - 3]));
  }
  const BSpline s = interpolate_cubic(p, t, ends);
  NurbsCurve3d::Points ctrl;
  for (int i = 0; i < s.size(); ++i) ctrl.push_back(s.coefs().col(i));
  return NurbsCurve3d(s.degree(), s.knots(), ctrl);
}

namespace {

double diameter(const Eigen::Matrix3Xd& points) {
  return (points.rowwise().maxCoeff() - points.rowwise().minCoeff()).norm();
}

// Everything after the spine: curvature, bounds (an infeasible radius refused or, allowed,
// warned about), the pipe surface; `size` scales the default tolerance.
void bound_and_skin(PipeJobResult& r, const PipeJobOptions& o, double size,
                    std::chrono::steady_clock::time_point t0) {
  r.length = SpineTable(r.spine, 64).length();
  r.curvature = max_curvature(r.spine);
  r.bounds = pipe_bounds(r.spine, r.closed);
  r.nonsingular = o.radius < r.bounds.delta;
  if (!r.nonsingular) {
    const auto at = [&](double t) {
      return r.chord_length_parameter ? number_text(t) + " mm along the spine"
                                      : "t = " + number_text(t) + " on the spine";
    };
    const std::string where = r.bounds.t1 == r.bounds.t2
                                  ? "at " + at(r.bounds.t1)
                                  : "between " + at(r.bounds.t1) + " and " + at(r.bounds.t2);
    const std::string what =
        "--radius " + number_text(o.radius) +
        " mm: the pipe self-intersects for radii at or beyond δ = " + number_text(r.bounds.delta) +
        " mm (" + r.bounds.limiting_mode + ", " + where + ")";
    if (!o.allow_self_intersection)
      throw InputError(r.input.string() + ": " + what +
                       "; use a smaller radius or --allow-self-intersection");
    r.warnings.push_back(what);
  }
  r.tolerance = o.tolerance > 0 ? o.tolerance : 1e-4 * size;
  // A self-intersecting pipe folds into cusps no skinning follows to a tolerance: it is skinned
  // once (a station per knot span) and its measured deviation reported.
  r.pipe = pipe_surface(r.spine, o.radius, o.frame,
                        r.nonsingular ? r.tolerance : std::numeric_limits<double>::max());
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The result's input and options, after checking the radius.
PipeJobResult started(const std::filesystem::path& input, const PipeJobOptions& o) {
  if (!(o.radius > 0) || !std::isfinite(o.radius))
    throw InputError("--radius: expected a positive length in mm");
  PipeJobResult r;
  r.input = input;
  r.radius = o.radius;
  r.frame = o.frame;
  return r;
}

}  // namespace

PipeJobResult run_pipe_job(const std::filesystem::path& file, const PipeJobOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  PipeJobResult r = started(file, o);
  r.points = read_spine_csv(file);
  const double size = diameter(r.points);
  const bool ends_meet =
      (r.points.col(0) - r.points.col(r.points.cols() - 1)).norm() <= 1e-9 * size;
  r.closed =
      o.closure == SpineClosure::closed || (o.closure == SpineClosure::automatic && ends_meet);
  Eigen::Matrix3Xd pts = r.points;
  if (r.closed && !ends_meet) {  // --closed yes: the loop returns to its first point
    pts.conservativeResize(3, pts.cols() + 1);
    pts.col(pts.cols() - 1) = pts.col(0);
  }
  if (r.closed && pts.cols() < 4)
    throw InputError(file.string() + ": a closed spine needs at least 3 distinct points");
  r.spine = spine_through(pts, r.closed);
  bound_and_skin(r, o, size, t0);
  return r;
}

PipeJobResult run_pipe_job(const std::filesystem::path& input, const NurbsCurve3d& spine,
                           const PipeJobOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  PipeJobResult r = started(input, o);
  r.spine = spine;
  r.chord_length_parameter = false;
  r.points.resize(3, spine.size());
  for (int i = 0; i < spine.size(); ++i) r.points.col(i) = spine.control_point(i);
  const double size = diameter(r.points);
  const double gap = (spine.point(spine.front()) - spine.point(spine.back())).norm();
  const bool ends_meet = gap <= 1e-9 * size;
  if (o.closure == SpineClosure::closed && !ends_meet)
    throw InputError(input.string() + ": a closed spine (closed yes) but its ends are " +
                     number_text(gap) + " mm apart");
  r.closed = o.closure != SpineClosure::open && ends_meet;
  bound_and_skin(r, o, size, t0);
  return r;
}

}  // namespace polarform
