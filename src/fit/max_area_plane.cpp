// Maximum-area plane of a surface blanket (Piegl & Tiller 2001, §3.2; spec P5): the vector area,
// the seed's eigenvector of Σ A_k A_kᵀ, the total-least-squares plane and the fold count.
#include "src/fit/max_area_plane.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>

namespace polarform {

// Piegl & Tiller 2001, §3.2 (max projected area); spec P5 (N* = A/|A|, exact eigenvector, folds).
MaxAreaPlane max_area_plane(const SurfaceBlanket& blanket) {
  MaxAreaPlane r;
  std::vector<Eigen::Vector3d> areas;
  areas.reserve(2 * static_cast<std::size_t>(std::max(0, blanket.quads())));
  const auto P = [&](int a, int b) { return blanket.points.col(blanket.vertex(a, b)); };
  for (int a = 0; a < blanket.quads_u(); ++a)
    for (int b = 0; b < blanket.quads_v(); ++b) {
      const Eigen::Vector3d p00 = P(a, b), p10 = P(a + 1, b), p11 = P(a + 1, b + 1),
                            p01 = P(a, b + 1);
      areas.push_back(0.5 * (p10 - p00).cross(p11 - p00));
      areas.push_back(0.5 * (p11 - p00).cross(p01 - p00));
    }
  Eigen::Vector3d A = Eigen::Vector3d::Zero();
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& a : areas) {
    A += a;
    M += a * a.transpose();
    r.area += a.norm();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(M);
  r.eigen_normal = eig.eigenvectors().col(2);
  if (r.eigen_normal.dot(A) < 0.0) r.eigen_normal = -r.eigen_normal;
  // A closed blanket (a full cylinder) has A ≈ 0: the eigenvector is the only direction left.
  r.normal = A.norm() > 1e-12 * r.area ? Eigen::Vector3d(A.normalized()) : r.eigen_normal;
  r.angle_between_deg =
      std::acos(std::min(1.0, std::abs(r.normal.dot(r.eigen_normal)))) * 180.0 / std::numbers::pi;
  for (const Eigen::Vector3d& a : areas) {
    const double projected = a.dot(r.normal);
    r.projected_area += projected;
    // Collapsed triangles (a degenerate boundary edge) have no orientation and do not fold.
    if (projected <= 0.0 && a.norm() > 1e-12 * r.area) ++r.folded_triangles;
  }
  const Eigen::Index n = blanket.points.cols();
  r.centroid = n > 0 ? Eigen::Vector3d(blanket.points.rowwise().mean()) : Eigen::Vector3d::Zero();
  const Eigen::Matrix3Xd centred = blanket.points.colwise() - r.centroid;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> tls(centred * centred.transpose());
  r.lsq_normal = tls.eigenvectors().col(0);  // smallest scatter: total least squares
  return r;
}

}  // namespace polarform
