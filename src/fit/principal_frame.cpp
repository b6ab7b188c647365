// PCA object frame and bounding box (Kantz 2003, §5.1).
#include "src/fit/principal_frame.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "src/error.h"

namespace polarform {

// Kantz 2003, eqs. (5.1)–(5.6), eigenvectors by Eigen's SelfAdjointEigenSolver.
PrincipalFrame principal_frame(const Eigen::Matrix3Xd& points) {
  const Eigen::Index n = points.cols();
  if (n < 3) throw InputError("principal frame: " + std::to_string(n) + " points, need at least 3");
  if (!points.allFinite()) throw InputError("principal frame: a point has a non-finite coordinate");
  PrincipalFrame f;
  f.centroid = points.rowwise().mean();
  const Eigen::Matrix3Xd d = points.colwise() - f.centroid;
  const Eigen::Matrix3d C = d * d.transpose() / static_cast<double>(n);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
  for (int i = 0; i < 3; ++i) {  // descending
    f.eigenvalues[i] = es.eigenvalues()[2 - i];
    f.axes.col(i) = es.eigenvectors().col(2 - i);
  }
  for (int i = 0; i < 2; ++i) {  // third moments fix the signs
    const Eigen::VectorXd s = d.transpose() * f.axes.col(i);
    if (s.array().cube().sum() < 0.0) f.axes.col(i) *= -1.0;
  }
  f.axes.col(2) = f.axes.col(0).cross(f.axes.col(1));
  const Eigen::Matrix3Xd local = f.axes.transpose() * points;
  f.box_low = local.rowwise().minCoeff();
  f.box_high = local.rowwise().maxCoeff();
  f.box_centre = f.axes * (0.5 * (f.box_low + f.box_high));
  return f;
}

int PrincipalFrame::axis_index(FrameAxis rule) const {
  switch (rule) {
    case FrameAxis::principal:
      return 0;
    case FrameAxis::smallest:
      return 2;
    case FrameAxis::most_distinct:
      break;
  }
  // The eigenvalue farthest from the other two: λ_0 when λ_0 − λ_1 > λ_1 − λ_2, else λ_2.
  return eigenvalues[0] - eigenvalues[1] > eigenvalues[1] - eigenvalues[2] ? 0 : 2;
}

double PrincipalFrame::tie_ratio(FrameAxis rule) const {
  const int a = axis_index(rule);
  const int b = (a + 1) % 3, c = (a + 2) % 3;
  return eigenvalues[0] > 0.0 ? std::abs(eigenvalues[b] - eigenvalues[c]) / eigenvalues[0] : 0.0;
}

}  // namespace polarform
