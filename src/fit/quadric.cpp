#include "src/fit/quadric.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "src/error.h"

namespace polarform {

std::string to_string(QuadricType t) {
  switch (t) {
    case QuadricType::real_ellipsoid: return "real ellipsoid";
    case QuadricType::imaginary_ellipsoid: return "imaginary ellipsoid";
    case QuadricType::hyperboloid_of_one_sheet: return "hyperboloid of one sheet";
    case QuadricType::hyperboloid_of_two_sheets: return "hyperboloid of two sheets";
    case QuadricType::real_quadric_cone: return "real quadric cone";
    case QuadricType::imaginary_quadric_cone: return "imaginary quadric cone";
    case QuadricType::elliptic_paraboloid: return "elliptic paraboloid";
    case QuadricType::hyperbolic_paraboloid: return "hyperbolic paraboloid";
    case QuadricType::real_elliptic_cylinder: return "real elliptic cylinder";
    case QuadricType::imaginary_elliptic_cylinder: return "imaginary elliptic cylinder";
    case QuadricType::hyperbolic_cylinder: return "hyperbolic cylinder";
    case QuadricType::real_intersecting_planes: return "real intersecting planes";
    case QuadricType::imaginary_intersecting_planes: return "imaginary intersecting planes";
    case QuadricType::parabolic_cylinder: return "parabolic cylinder";
    case QuadricType::real_parallel_planes: return "real parallel planes";
    case QuadricType::imaginary_parallel_planes: return "imaginary parallel planes";
    case QuadricType::coincident_planes: return "coincident planes";
    case QuadricType::plane: return "plane";
  }
  return "unknown";
}

bool defines_frame(QuadricType t) {
  return t == QuadricType::real_ellipsoid || t == QuadricType::hyperboloid_of_one_sheet ||
         t == QuadricType::hyperboloid_of_two_sheets || t == QuadricType::real_quadric_cone ||
         t == QuadricType::elliptic_paraboloid || t == QuadricType::real_elliptic_cylinder;
}

Eigen::Matrix3d Quadric::Qu() const {
  Eigen::Matrix3d m;
  m << q[0], q[3] / 2, q[5] / 2,  //
      q[3] / 2, q[1], q[4] / 2,   //
      q[5] / 2, q[4] / 2, q[2];
  return m;
}

Eigen::Matrix4d Quadric::Q() const {
  Eigen::Matrix4d m;
  m.topLeftCorner<3, 3>() = Qu();
  m.topRightCorner<3, 1>() = v() / 2;
  m.bottomLeftCorner<1, 3>() = v().transpose() / 2;
  m(3, 3) = d();
  return m;
}

Quadric Quadric::from_matrix(const Eigen::Matrix4d& Q) {
  const Eigen::Matrix4d S = (Q + Q.transpose()) / 2;
  Quadric r;
  r.q << S(0, 0), S(1, 1), S(2, 2), 2 * S(0, 1), 2 * S(1, 2), 2 * S(0, 2), 2 * S(0, 3),
      2 * S(1, 3), 2 * S(2, 3), S(3, 3);
  return r;
}

double Quadric::operator()(const Eigen::Vector3d& x) const {
  return x.dot(Qu() * x) + v().dot(x) + d();
}

Eigen::Vector3d Quadric::gradient(const Eigen::Vector3d& x) const { return 2 * Qu() * x + v(); }

Quadric Quadric::substituted(const Eigen::Matrix3d& A, const Eigen::Vector3d& t) const {
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T.topLeftCorner<3, 3>() = A;
  T.topRightCorner<3, 1>() = t;
  return from_matrix(T.transpose() * Q() * T);
}

// Bae 2002, Table 4.1.
QuadricClassification classify_quadric(const Quadric& quadric, double L, double tol) {
  if (!(L > 0.0) || !(tol >= 0.0))
    throw InputError("quadric classification: length scale and tolerance must be > 0 and >= 0");
  if (quadric.q.cwiseAbs().maxCoeff() == 0.0)
    throw InputError("quadric classification: every coefficient is zero");
  QuadricClassification c;
  c.tolerance = tol;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(quadric.Qu());
  c.eigenvalues = es.eigenvalues();
  c.eigenvectors = es.eigenvectors();
  const double lmax = c.eigenvalues.cwiseAbs().maxCoeff();
  const Eigen::Vector3d b = c.eigenvectors.transpose() * quadric.v();
  // Canonical form: Σ λ_i y_i² (non-zero λ) + β·(null-space coordinate) + d' = 0.
  double dprime = quadric.d(), beta2 = 0.0;
  int positive = 0, negative = 0;
  for (int i = 0; i < 3; ++i) {
    const double l = c.eigenvalues[i];
    if (lmax > 0.0 && std::abs(l) > tol * lmax) {
      dprime -= b[i] * b[i] / (4 * l);
      (l > 0 ? positive : negative)++;
    } else {
      c.zero_eigenvalue[i] = 1.0;
      beta2 += b[i] * b[i];
    }
  }
  c.rank_Qu = positive + negative;
  c.k_same = positive == 0 || negative == 0;
  const double scale = lmax * L * L;
  const bool beta = lmax > 0.0 ? std::sqrt(beta2) * L > tol * scale : beta2 > 0.0;
  const bool dnz = !beta && std::abs(dprime) > tol * scale;
  if (c.rank_Qu == 0) {
    c.type = QuadricType::plane;
    c.rank_Q = beta ? 2 : 1;
    return c;
  }
  c.rank_Q = c.rank_Qu + (beta ? 2 : dnz ? 1 : 0);
  // Signs of Q's non-zero eigenvalues (inertia is invariant under the congruences used): β adds
  // one of each sign, d' its own.
  const int Kpos = positive + (beta ? 1 : 0) + (dnz && dprime > 0 ? 1 : 0);
  const int Kneg = negative + (beta ? 1 : 0) + (dnz && dprime < 0 ? 1 : 0);
  c.K_same = Kpos == 0 || Kneg == 0;
  if (c.rank_Q == 4) c.det_sign = (negative % 2 == 0 ? 1 : -1) * (beta ? -1 : (dprime > 0 ? 1 : -1));
  using T = QuadricType;
  switch (c.rank_Qu) {
    case 3:
      if (c.rank_Q == 4) {
        if (c.det_sign < 0) c.type = c.k_same ? T::real_ellipsoid : T::hyperboloid_of_two_sheets;
        else c.type = c.k_same ? T::imaginary_ellipsoid : T::hyperboloid_of_one_sheet;
      } else {
        c.type = c.k_same ? T::imaginary_quadric_cone : T::real_quadric_cone;
      }
      break;
    case 2:
      if (c.rank_Q == 4) c.type = c.det_sign < 0 ? T::elliptic_paraboloid : T::hyperbolic_paraboloid;
      else if (c.rank_Q == 3)
        c.type = !c.k_same ? T::hyperbolic_cylinder
                           : (c.K_same ? T::imaginary_elliptic_cylinder : T::real_elliptic_cylinder);
      else c.type = c.k_same ? T::imaginary_intersecting_planes : T::real_intersecting_planes;
      break;
    default:
      if (c.rank_Q == 3) c.type = T::parabolic_cylinder;
      else if (c.rank_Q == 2) c.type = c.K_same ? T::imaginary_parallel_planes : T::real_parallel_planes;
      else c.type = T::coincident_planes;
      break;
  }
  return c;
}

}  // namespace polarform
