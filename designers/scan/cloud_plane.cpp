#include "designers/scan/cloud_plane.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "src/error.h"

namespace polarform {

CloudPlane fit_plane(const Eigen::Matrix3Xd& points, const std::optional<Eigen::Vector3d>& normal) {
  if (points.cols() < 3)
    throw InputError("plane fit: " + std::to_string(points.cols()) +
                     " points, expected at least 3");
  if (!points.allFinite()) throw InputError("plane fit: a point is not finite");
  const Eigen::Vector3d centroid = points.rowwise().mean();
  const Eigen::Matrix3Xd centred = points.colwise() - centroid;
  Eigen::Vector3d k;
  if (normal) {
    if (!(normal->norm() > 0.0) || !normal->allFinite())
      throw InputError("plane fit: the axis must be a finite non-zero vector");
    k = normal->normalized();
  } else {
    // Total least squares: the direction of least scatter.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(centred * centred.transpose());
    k = es.eigenvectors().col(0);
    if (k.z() < 0 || (k.z() == 0 && (k.x() < 0 || (k.x() == 0 && k.y() < 0)))) k = -k;
  }
  CloudPlane p;
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  if (k.cross(z).norm() <= 1e-4 && k.dot(z) > 0) {
    p.snapped = true;
    p.frame.origin = Eigen::Vector3d(0, 0, centroid.z());
    p.frame.axes = Eigen::Matrix3d::Identity();
  } else {
    const Eigen::Vector3d seed =
        std::abs(k.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    const Eigen::Vector3d i = (seed - k * k.dot(seed)).normalized();
    p.frame.origin = centroid;
    p.frame.axes.col(0) = i;
    p.frame.axes.col(1) = k.cross(i);
    p.frame.axes.col(2) = k;
  }
  const Eigen::VectorXd h = (points.colwise() - p.frame.origin).transpose() * p.frame.axes.col(2);
  p.rms_distance = std::sqrt(h.squaredNorm() / static_cast<double>(h.size()));
  p.max_distance = h.cwiseAbs().maxCoeff();
  const Eigen::VectorXd along = centred.transpose() * p.frame.axes.col(2);
  p.size = std::sqrt(std::max(0.0, centred.squaredNorm() - along.squaredNorm()) /
                     static_cast<double>(h.size()));
  return p;
}

}  // namespace polarform
