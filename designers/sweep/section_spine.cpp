// Spine, frames and spine coordinates of a section sweep (MIT 13.472J §8.6).
#include "designers/sweep/section_spine.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "src/error.h"
#include "src/fit/curve_distance.h"
#include "src/fit/parallel.h"
#include "src/nurbs/curve_interpolation.h"

namespace polarform {

namespace {

// The frame turned by the smallest rotation that takes its tangent to t (Rodrigues' formula): the
// rotation-minimising frame between two close tangents to third order (Wang et al. 2008, §3).
SpineFrame turned(SpineFrame f, const Eigen::Vector3d& t) {
  const Eigen::Vector3d v = f.tangent.cross(t);
  const double c = f.tangent.dot(t);
  if (c > -0.5) {
    f.x = f.x * c + v.cross(f.x) + v * (v.dot(f.x) / (1.0 + c));
    f.x = (f.x - t * t.dot(f.x)).normalized();
  }
  f.tangent = t;
  f.y = t.cross(f.x);
  return f;
}

}  // namespace

SectionSpine::SectionSpine(NurbsCurve3d curve, bool straight, const Eigen::Vector3d& x_hint)
    : curve_(std::make_shared<const NurbsCurve3d>(std::move(curve))), straight_(straight) {
  table_ = std::make_shared<const SpineTable>(*curve_, 256);
  std::vector<double> ts;
  for (int i = 0; i < table_->size(); ++i) ts.push_back(table_->t(i));
  nodes_ = spine_frames(*curve_, ts, FrameRule::rmf, &x_hint);
}

SectionSpine SectionSpine::straight(const Eigen::Vector3d& start, const Eigen::Vector3d& direction,
                                    double length, const Eigen::Vector3d& x_hint) {
  if (!(direction.norm() > 0.0) || !(length > 0.0))
    throw InputError("section spine: a zero direction or length");
  const Eigen::Vector3d d = direction.normalized();
  return SectionSpine(NurbsCurve3d(1, {0, 0, length, length}, {start, start + length * d}), true,
                      x_hint);
}

SectionSpine SectionSpine::through(const std::vector<Eigen::Vector3d>& centres,
                                   const Eigen::Vector3d& x_hint) {
  const int n = static_cast<int>(centres.size());
  if (n < 3) throw InputError("section spine: " + std::to_string(n) + " centres, need 3");
  std::vector<double> t(static_cast<std::size_t>(n), 0.0);
  for (int k = 1; k < n; ++k) t[k] = t[k - 1] + (centres[k] - centres[k - 1]).norm();
  // The parabola through three centres at parameters a, b, e (Lagrange), at x.
  auto parabola = [](const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                     const Eigen::Vector3d& p2, double a, double b, double e, double x) {
    return Eigen::Vector3d(p0 * ((x - b) * (x - e) / ((a - b) * (a - e))) +
                           p1 * ((x - a) * (x - e) / ((b - a) * (b - e))) +
                           p2 * ((x - a) * (x - b) / ((e - a) * (e - b))));
  };
  const double ext = 0.25 * t[n - 1];
  const double t0 = -ext, t1 = t[n - 1] + ext;
  Eigen::MatrixXd values(3, n + 2);
  Eigen::VectorXd params(n + 2);
  values.col(0) = parabola(centres[0], centres[1], centres[2], t[0], t[1], t[2], t0);
  params[0] = t0;
  for (int k = 0; k < n; ++k) {
    values.col(k + 1) = centres[k];
    params[k + 1] = t[k];
  }
  values.col(n + 1) =
      parabola(centres[n - 3], centres[n - 2], centres[n - 1], t[n - 3], t[n - 2], t[n - 1], t1);
  params[n + 1] = t1;
  const CubicEnds ends = bessel_ends(values, params);
  const BSpline b = interpolate_cubic(values, params, ends);
  NurbsCurve3d::Points q;
  for (int i = 0; i < b.size(); ++i) q.push_back(b.coefs().col(i));
  return SectionSpine(NurbsCurve3d(3, b.knots(), q), false, x_hint);
}

SpineFrame SectionSpine::frame_at(double t, double s) const {
  const auto up = std::upper_bound(nodes_.begin(), nodes_.end(), t,
                                   [](double a, const SpineFrame& f) { return a < f.t; });
  const SpineFrame& node = up == nodes_.begin() ? nodes_.front() : *(up - 1);
  const auto d = curve_->derivatives(t, 1);
  SpineFrame f = turned(node, d[1].normalized());
  f.t = s;
  f.point = d[0];
  return f;
}

SpineFrame SectionSpine::frame(double s) const {
  const double L = length();
  if (s < 0.0 || s > L) {
    SpineFrame f = s < 0.0 ? nodes_.front() : nodes_.back();
    f.point += (s < 0.0 ? s : s - L) * f.tangent;
    f.t = s;
    return f;
  }
  return frame_at(table_->parameter_at(s), s);
}

Eigen::Vector3d SectionSpine::point(double s, double x, double y) const {
  const SpineFrame f = frame(s);
  return f.point + x * f.x + y * f.y;
}

Eigen::Matrix3Xd SectionSpine::coordinates(const Eigen::Matrix3Xd& points, int threads) const {
  const CurveDistance<3> distance(*curve_);
  const double L = length();
  Eigen::Matrix3Xd out(3, points.cols());
  const auto n = static_cast<std::size_t>(points.cols());
  parallel_chunks(n, worker_count(threads, n, 2000), [&](std::size_t b, std::size_t e, int) {
    for (std::size_t k = b; k < e; ++k) {
      const Eigen::Vector3d p = points.col(static_cast<Eigen::Index>(k));
      const double t = distance.project(p).u;
      SpineFrame f;
      double s = table_->arc_length(t);
      if (t <= curve_->front() || t >= curve_->back()) {
        // Beyond an end: along the end tangent.
        const SpineFrame& end = t <= curve_->front() ? nodes_.front() : nodes_.back();
        const double along = (p - end.point).dot(end.tangent);
        if ((t <= curve_->front()) == (along < 0.0)) s = (t <= curve_->front() ? 0.0 : L) + along;
        f = frame(s);
      } else {
        f = frame_at(t, s);
      }
      const Eigen::Vector3d r = p - f.point;
      out.col(static_cast<Eigen::Index>(k)) << s, r.dot(f.x), r.dot(f.y);
    }
  });
  return out;
}

}  // namespace polarform
