// The object frame of a point cloud by principal component analysis and its bounding box (Kantz
// 2003, §5.1, eqs. (5.1)–(5.6)): centroid, covariance, eigenvectors (a symmetric eigensolver, not
// the characteristic polynomial), the box in the eigenframe and its centre, and the choice of an
// axis (principal, most distinct, smallest) with the tie ratio of the other two eigenvalues, the
// evidence (necessary, not sufficient) of rotational symmetry about the most distinct one.
#pragma once

#include <Eigen/Core>

namespace polarform {

enum class FrameAxis {
  principal,      // largest eigenvalue: the direction along which the data vary most (Kantz)
  most_distinct,  // the eigenvalue farthest from the other two: a symmetry axis
  smallest,       // smallest eigenvalue: a plate's normal
};

struct PrincipalFrame {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();     // eq. (5.1)
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();  // of the covariance (5.2), descending
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();     // columns: the eigenvectors, right-handed
  Eigen::Vector3d box_low = Eigen::Vector3d::Zero();      // min ⟨V_i, P⟩ per axis
  Eigen::Vector3d box_high = Eigen::Vector3d::Zero();     // max ⟨V_i, P⟩ per axis
  Eigen::Vector3d box_centre = Eigen::Vector3d::Zero();  // Σ V_i (min_i + max_i)/2 (Kantz's origin)

  // The column of `axes` chosen by the rule, and the tie ratio |λ_a − λ_b| / λ_max of the other
  // two eigenvalues (0: a perfect tie).
  int axis_index(FrameAxis rule) const;
  Eigen::Vector3d axis(FrameAxis rule) const { return axes.col(axis_index(rule)); }
  double tie_ratio(FrameAxis rule) const;
};

// Needs at least 3 points, all finite (InputError otherwise). Eigenvector signs follow the third
// moments (the skew of the data along each axis is made >= 0), so the frame moves with the data.
PrincipalFrame principal_frame(const Eigen::Matrix3Xd& points);

}  // namespace polarform
