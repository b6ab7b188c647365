#include "src/fit/circle_fit.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>

#include "src/error.h"

namespace polarform {

// Taubin 1991 for circles: minimise Σ (A z + B x + C y + D)² subject to mean |∇|² = 1, with
// z = x² + y² on centred data; D = −A·mean(z) eliminated.
CircleFit fit_circle(const Eigen::Matrix2Xd& points) {
  const Eigen::Index n = points.cols();
  if (n < 3) throw InputError("circle fit: " + std::to_string(n) + " points, expected at least 3");
  if (!points.allFinite()) throw InputError("circle fit: a point is not finite");
  const Eigen::Vector2d c = points.rowwise().mean();
  const Eigen::Matrix2Xd p = points.colwise() - c;
  const double s = std::sqrt(p.colwise().squaredNorm().mean());
  if (!(s > 0.0)) throw InputError("circle fit: all points coincide");
  const Eigen::Matrix2Xd q = p / s;
  const Eigen::RowVectorXd z = q.colwise().squaredNorm();
  const double zbar = z.mean();  // = 1 after scaling
  Eigen::Matrix3Xd m(3, n);
  m.row(0) = z.array() - zbar;
  m.row(1) = q.row(0);
  m.row(2) = q.row(1);
  const Eigen::Matrix3d M = m * m.transpose() / static_cast<double>(n);
  const Eigen::Matrix3d N = Eigen::Vector3d(4 * zbar, 1, 1).asDiagonal();
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix3d> ges(M, N);
  const Eigen::Vector3d a = ges.eigenvectors().col(0);
  if (!(std::abs(a[0]) > 1e-12 * a.norm()))
    throw InputError("circle fit: the points lie on a straight line (no finite centre)");
  CircleFit out;
  out.centre = c + s * Eigen::Vector2d(-a[1] / (2 * a[0]), -a[2] / (2 * a[0]));
  const Eigen::ArrayXd r = (points.colwise() - out.centre).colwise().norm().transpose().array();
  out.radius = r.mean();
  out.rms = std::sqrt((r - out.radius).square().mean());
  return out;
}

}  // namespace polarform
