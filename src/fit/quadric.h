// General quadric surfaces q(x) = x^T Q_u x + v^T x + d = 0 (Bae 2002, eq. (4.1)) and their
// classification into the 17 types of Table 4.1 (after Zwillinger 1996). The ranks and signs of
// the table are read off a canonical form (rotation to the eigenvectors of Q_u, completing the
// squares, a translation along Q_u's null space), with "zero" judged relative to the largest
// quadratic term over a length scale of the data, so the decisions scale with the data.
#pragma once

#include <Eigen/Core>
#include <string>

namespace polarform {

enum class QuadricType {
  real_ellipsoid,
  imaginary_ellipsoid,
  hyperboloid_of_one_sheet,
  hyperboloid_of_two_sheets,
  real_quadric_cone,
  imaginary_quadric_cone,
  elliptic_paraboloid,
  hyperbolic_paraboloid,
  real_elliptic_cylinder,
  imaginary_elliptic_cylinder,
  hyperbolic_cylinder,
  real_intersecting_planes,
  imaginary_intersecting_planes,
  parabolic_cylinder,
  real_parallel_planes,
  imaginary_parallel_planes,
  coincident_planes,
  plane,  // Q_u = 0: a linear equation, outside Table 4.1
};

std::string to_string(QuadricType type);

// True for the six types that define a local frame (Bae 2002, §4.3, Fig. 4.2).
bool defines_frame(QuadricType type);

struct Quadric {
  // q1..q10 of Bae 2002, eq. (4.1): x², y², z², xy, yz, zx, x, y, z, 1.
  Eigen::Matrix<double, 10, 1> q = Eigen::Matrix<double, 10, 1>::Zero();

  Eigen::Matrix3d Qu() const;
  Eigen::Vector3d v() const { return q.segment<3>(6); }
  double d() const { return q[9]; }
  Eigen::Matrix4d Q() const;  // eq. (4.1b)
  static Quadric from_matrix(const Eigen::Matrix4d& Q);

  double operator()(const Eigen::Vector3d& x) const;
  Eigen::Vector3d gradient(const Eigen::Vector3d& x) const;
  // The same surface after the affine change of coordinates x = A y + t (as a quadric in y).
  Quadric substituted(const Eigen::Matrix3d& A, const Eigen::Vector3d& t) const;
};

struct QuadricClassification {
  QuadricType type = QuadricType::plane;
  int rank_Qu = 0, rank_Q = 0;
  int det_sign = 0;           // sign of det Q (0 when rank Q < 4)
  bool k_same = true;         // the non-zero eigenvalues of Q_u share one sign ("k: =")
  bool K_same = true;         // the non-zero eigenvalues of Q share one sign ("K: =")
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();   // of Q_u, ascending
  Eigen::Matrix3d eigenvectors = Eigen::Matrix3d::Identity();  // matching unit columns
  Eigen::Vector3d zero_eigenvalue = Eigen::Vector3d::Zero();   // 1 where an eigenvalue counts as 0
  double tolerance = 0.0;
};

// Table 4.1. A quantity counts as zero when, over `length_scale` L (the data's size), its effect is
// at most `tolerance` times the largest quadratic term λ_max·L²: eigenvalues |λ| ≤ tol·λ_max, the
// linear term left in Q_u's null space |β|·L ≤ tol·λ_max·L², the completed constant
// |d'| ≤ tol·λ_max·L². Throws InputError when every coefficient is zero.
QuadricClassification classify_quadric(const Quadric& quadric, double length_scale, double tolerance);

}  // namespace polarform
