// Robust Gauss–Newton refinement of an extrusion direction against its section (Kantz 2003,
// §5.2.1).
#include "designers/sweep/extrusion_direction.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>

#include "src/fit/robust_weights.h"

namespace polarform {

Eigen::Matrix2Xd project_onto_plane(const Eigen::Matrix3Xd& P, const Eigen::Vector3d& c,
                                    const Eigen::Vector3d& e1, const Eigen::Vector3d& e2) {
  Eigen::Matrix<double, 2, 3> B;
  B.row(0) = e1.transpose();
  B.row(1) = e2.transpose();
  return B * (P.colwise() - c);
}

DirectionRefinement refine_extrusion_direction(const Eigen::Matrix3Xd& P,
                                               const Eigen::Vector3d& origin,
                                               const Eigen::Vector3d& start,
                                               const MeridianModel& model,
                                               const AxisRefinementOptions& o) {
  DirectionRefinement out;
  out.direction = start.normalized();
  for (int it = 0; it < o.max_iterations; ++it) {
    const Eigen::Vector3d d = out.direction;
    const auto [e1, e2] = normal_pair(d);
    const Eigen::Matrix2Xd q = project_onto_plane(P, origin, e1, e2);
    const Eigen::VectorXd h = (P.colwise() - origin).transpose() * d;
    const MeridianResiduals res = model(q);
    Eigen::VectorXd r = res.distance;
    for (Eigen::Index k = 0; k < r.size(); ++k)
      if (!res.valid[k] || !std::isfinite(r[k])) r[k] = 0.0;
    const Eigen::VectorXd w = tukey_weights(r, std::max(o.scale_floor, 1e-12 * o.size));
    Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
    Eigen::Vector2d g = Eigen::Vector2d::Zero();
    double wrr = 0.0, wsum = 0.0;
    for (Eigen::Index k = 0; k < r.size(); ++k) {
      if (!res.valid[k] || w[k] == 0.0) continue;
      const Eigen::Vector2d j(h[k] * res.normal(1, k), -h[k] * res.normal(0, k));
      A += w[k] * j * j.transpose();
      g += w[k] * j * r[k];
      wrr += w[k] * r[k] * r[k];
      wsum += w[k];
    }
    if (wsum < 8.0) break;
    const double rms = std::sqrt(wrr / wsum);
    if (it == 0) out.rms_before = rms;
    out.rms_after = rms;
    A.diagonal().array() += 1e-14 * std::max(A.trace(), 1e-300);
    const Eigen::Matrix2d inverse = A.ldlt().solve(Eigen::Matrix2d::Identity());
    if (wsum > 2.0) out.covariance = wrr / (wsum - 2.0) * inverse;
    Eigen::Vector2d s = -inverse * g;
    if (s.norm() > 0.05) s *= 0.05 / s.norm();
    out.direction = (d - s[0] * e2 + s[1] * e1).normalized();  // d + (a e1 + b e2) × d
    out.iterations = it + 1;
    if (s.norm() * o.size <= o.step_tolerance * o.size) {
      out.converged = true;
      break;
    }
  }
  return out;
}

}  // namespace polarform
