// Rotation-axis refinement by robust Gauss–Newton on meridian residuals (spec K11 step 4).
#include "src/fit/rotation_axis.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "src/fit/error_stats.h"
#include "src/fit/grid_index.h"
#include "src/fit/parallel.h"
#include "src/fit/robust_weights.h"

namespace polarform {

// Gram–Schmidt of x (of y when |a_x| >= 0.6) against a.
std::pair<Eigen::Vector3d, Eigen::Vector3d> normal_pair(const Eigen::Vector3d& a) {
  const Eigen::Vector3d t =
      std::abs(a.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d e1 = (t - t.dot(a) * a).normalized();
  return {e1, a.cross(e1)};
}

namespace {

// ∂(z, r)/∂(α, β, γ, δ) for a(α, β) = normalize(a + α e1 + β e2), c(γ, δ) = c + γ e1 + δ e2, at 0:
// ∂z = (e1·w, e2·w, 0, 0), ∂r = (−z u·e1, −z u·e2, −u·e1, −u·e2), w = p − c, u = (w − z a)/r.
Eigen::Matrix<double, 2, 4> meridian_jacobian(const Eigen::Vector3d& p, const AxisLine& axis,
                                              const Eigen::Vector3d& e1,
                                              const Eigen::Vector3d& e2) {
  const Eigen::Vector3d w = p - axis.point;
  const double z = w.dot(axis.direction);
  const Eigen::Vector3d v = w - z * axis.direction;
  const double r = v.norm();
  Eigen::Matrix<double, 2, 4> J;
  J.row(0) << e1.dot(w), e2.dot(w), 0.0, 0.0;
  if (r > 0.0) {
    const Eigen::Vector3d u = v / r;
    J.row(1) << -z * u.dot(e1), -z * u.dot(e2), -u.dot(e1), -u.dot(e2);
  } else {
    J.row(1).setZero();
  }
  return J;
}

// Applies the step (α, β, γ, δ) and moves the axis point to the foot of the centroid.
AxisLine apply_step(const AxisLine& axis, const Eigen::Vector4d& step,
                    const Eigen::Vector3d& centroid) {
  const auto [e1, e2] = normal_pair(axis.direction);
  AxisLine next;
  next.direction = (axis.direction + step[0] * e1 + step[1] * e2).normalized();
  next.point = axis.point + step[2] * e1 + step[3] * e2;
  next.point += (centroid - next.point).dot(next.direction) * next.direction;
  return next;
}

struct Normal4 {
  Eigen::Matrix4d JtJ = Eigen::Matrix4d::Zero();
  Eigen::Vector4d Jtr = Eigen::Vector4d::Zero();
  double wrr = 0.0, w = 0.0;
};

// The Gauss–Newton step; the parameters a fixed direction or point freezes stay 0.
Eigen::Vector4d solve_step(const Normal4& N, const AxisRefinementOptions& o) {
  Eigen::Matrix4d A = N.JtJ;
  Eigen::Vector4d g = N.Jtr;
  A.diagonal().array() += 1e-12 * std::max(A.trace(), 1e-300);
  for (int i = 0; i < 4; ++i) {
    if (i < 2 ? !o.fix_direction : !o.fix_point) continue;
    A.row(i).setZero(), A.col(i).setZero(), A(i, i) = 1.0, g[i] = 0.0;
  }
  Eigen::Vector4d s = -A.ldlt().solve(g);
  const double tilt = std::hypot(s[0], s[1]);
  if (tilt > 0.05) s *= 0.05 / tilt;  // a trust region on the direction
  return s;
}

Eigen::Matrix4d covariance(const Normal4& N) {
  if (N.w <= 4.0) return Eigen::Matrix4d::Zero();
  const double s2 = N.wrr / (N.w - 4.0);
  Eigen::Matrix4d A = N.JtJ;
  A.diagonal().array() += 1e-14 * std::max(A.trace(), 1e-300);
  return s2 * A.ldlt().solve(Eigen::Matrix4d::Identity());
}

bool small_step(const AxisLine& a, const AxisLine& b, const AxisRefinementOptions& o) {
  const double turn = (a.direction - b.direction).norm() * o.size;
  const Eigen::Vector3d d = b.point - a.point;
  const double shift = (d - d.dot(b.direction) * b.direction).norm();
  return turn + shift <= o.step_tolerance * o.size;
}

// One Gauss–Newton iteration's bookkeeping: rms and covariance recorded, the step applied;
// true when the axis moved less than the step tolerance.
bool take_step(AxisRefinement& out, const Normal4& N, int it, const Eigen::Vector3d& centroid,
               const AxisRefinementOptions& o) {
  const double rms = N.w > 0 ? std::sqrt(N.wrr / N.w) : 0.0;
  if (it == 0) out.rms_before = rms;
  out.rms_after = rms;
  out.covariance = covariance(N);
  const AxisLine next = apply_step(out.axis, solve_step(N, o), centroid);
  const bool done = small_step(out.axis, next, o);
  out.axis = next;
  out.iterations = it + 1;
  out.converged = done;
  return done;
}

}  // namespace

Eigen::Matrix2Xd meridian_coordinates(const Eigen::Matrix3Xd& points, const AxisLine& axis,
                                      int threads) {
  Eigen::Matrix2Xd zr(2, points.cols());
  const int chunks = worker_count(threads, static_cast<std::size_t>(points.cols()));
  parallel_chunks(
      static_cast<std::size_t>(points.cols()), chunks, [&](std::size_t b, std::size_t e, int) {
        for (std::size_t k = b; k < e; ++k) {
          const Eigen::Vector3d w = points.col(static_cast<Eigen::Index>(k)) - axis.point;
          const double z = w.dot(axis.direction);
          zr.col(static_cast<Eigen::Index>(k)) << z, (w - z * axis.direction).norm();
        }
      });
  return zr;
}

// Spec K11 step 4: Gauss–Newton on Σ w_k d_k², d_k the distance of (z_k, r_k) to the profile.
AxisRefinement refine_axis_by_profile(const Eigen::Matrix3Xd& points, const AxisLine& start,
                                      const MeridianModel& model, const AxisRefinementOptions& o) {
  AxisRefinement out;
  out.axis = start;
  // The line's point: the foot of the centroid, or the fixed point itself.
  const Eigen::Vector3d centroid = o.fix_point ? start.point : points.rowwise().mean();
  for (int it = 0; it < o.max_iterations; ++it) {
    const Eigen::Matrix2Xd zr = meridian_coordinates(points, out.axis, o.threads);
    const MeridianResiduals res = model(zr);
    Eigen::VectorXd d = res.distance;
    for (Eigen::Index k = 0; k < d.size(); ++k)
      if (!res.valid[k]) d[k] = std::numeric_limits<double>::infinity();
    Eigen::VectorXd finite = d;
    for (Eigen::Index k = 0; k < d.size(); ++k)
      if (!std::isfinite(finite[k])) finite[k] = 0.0;
    const Eigen::VectorXd w = tukey_weights(finite, std::max(o.scale_floor, 1e-12 * o.size));
    const auto [e1, e2] = normal_pair(out.axis.direction);
    Normal4 N;
    for (Eigen::Index k = 0; k < d.size(); ++k) {
      if (!res.valid[k] || w[k] == 0.0) continue;
      const Eigen::Matrix<double, 1, 4> j =
          res.normal.col(k).transpose() * meridian_jacobian(points.col(k), out.axis, e1, e2);
      N.JtJ += w[k] * j.transpose() * j;
      N.Jtr += w[k] * j.transpose() * d[k];
      N.wrr += w[k] * d[k] * d[k];
      N.w += w[k];
    }
    if (N.w < 8.0) break;
    if (take_step(out, N, it, centroid, o)) break;
  }
  return out;
}

int cluster_points(const Eigen::Matrix2Xd& P, double merge, int min_size, std::vector<int>& label) {
  const Eigen::Index n = P.cols();
  label.assign(static_cast<std::size_t>(n), -2);
  const GridIndex2d grid(P, std::max(merge, 1e-300) * 2.0);
  std::vector<int> queue, nb, members;
  int count = 0;
  for (Eigen::Index s = 0; s < n; ++s) {
    if (label[s] != -2) continue;
    members.clear();
    queue.assign(1, static_cast<int>(s));
    label[s] = count;
    while (!queue.empty()) {
      const int q = queue.back();
      queue.pop_back();
      members.push_back(q);
      grid.radius(P.col(q), merge, nb);
      for (int i : nb) {
        if (label[i] != -2) continue;
        label[i] = count;
        // A point (nearly) coincident with q adds no reach: it is not expanded (rings of exactly
        // equal (z, r) stay O(n)).
        if ((P.col(i) - P.col(q)).norm() > 1e-3 * merge)
          queue.push_back(i);
        else
          members.push_back(i);
      }
    }
    if (static_cast<int>(members.size()) >= min_size) {
      ++count;
    } else {
      for (int i : members) label[i] = -1;
    }
  }
  return count;
}

// Spec K11 step 3 (ring-structured meshes): Gauss–Newton on Σ |(z_k, r_k) − mean of its ring|².
AxisRefinement refine_axis_by_rings(const Eigen::Matrix3Xd& points, const AxisLine& start,
                                    double merge, const AxisRefinementOptions& o) {
  AxisRefinement out;
  out.axis = start;
  const Eigen::Vector3d centroid = o.fix_point ? start.point : points.rowwise().mean();
  std::vector<int> label;
  double eps = merge;
  for (int it = 0; it < o.max_iterations; ++it) {
    const Eigen::Matrix2Xd zr = meridian_coordinates(points, out.axis, o.threads);
    const int m = cluster_points(zr, eps, 3, label);
    if (m < 2) return out;
    const auto [e1, e2] = normal_pair(out.axis.direction);
    std::vector<Eigen::Matrix<double, 2, 4>> J(static_cast<std::size_t>(points.cols()));
    Eigen::Matrix2Xd mean_q = Eigen::Matrix2Xd::Zero(2, m);
    std::vector<Eigen::Matrix<double, 2, 4>> mean_J(static_cast<std::size_t>(m),
                                                    Eigen::Matrix<double, 2, 4>::Zero());
    Eigen::VectorXd count = Eigen::VectorXd::Zero(m);
    for (Eigen::Index k = 0; k < points.cols(); ++k) {
      if (label[k] < 0) continue;
      J[k] = meridian_jacobian(points.col(k), out.axis, e1, e2);
      mean_q.col(label[k]) += zr.col(k);
      mean_J[label[k]] += J[k];
      count[label[k]] += 1.0;
    }
    for (int c = 0; c < m; ++c) mean_q.col(c) /= count[c], mean_J[c] /= count[c];
    out.clustered = count.sum() / static_cast<double>(points.cols());
    Eigen::VectorXd spread = Eigen::VectorXd::Zero(points.cols());
    for (Eigen::Index k = 0; k < points.cols(); ++k)
      if (label[k] >= 0) spread[k] = (zr.col(k) - mean_q.col(label[k])).norm();
    const Eigen::VectorXd w = tukey_weights(spread, std::max(o.scale_floor, 1e-13 * o.size));
    Normal4 N;
    for (Eigen::Index k = 0; k < points.cols(); ++k) {
      if (label[k] < 0 || w[k] == 0.0) continue;
      const Eigen::Vector2d r = zr.col(k) - mean_q.col(label[k]);
      const Eigen::Matrix<double, 2, 4> j = J[k] - mean_J[label[k]];
      N.JtJ += w[k] * j.transpose() * j;
      N.Jtr += w[k] * j.transpose() * r;
      N.wrr += w[k] * r.squaredNorm();
      N.w += w[k];
    }
    const bool done = take_step(out, N, it, centroid, o);
    // The merge radius follows the typical (median) spread, so rings merged at a coarse radius
    // separate again as the axis improves.
    Eigen::VectorXd clustered(points.cols());
    Eigen::Index nc = 0;
    for (Eigen::Index k = 0; k < points.cols(); ++k)
      if (label[k] >= 0) clustered[nc++] = spread[k];
    eps = std::clamp(10.0 * abs_quantile(clustered.head(nc), 0.5), 1e-9 * o.size, merge);
    if (done) break;
  }
  return out;
}

}  // namespace polarform
