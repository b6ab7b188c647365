#include "src/fit/quadric_fit.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>
#include <vector>

#include "src/error.h"
#include "src/fit/parallel.h"

namespace polarform {

namespace {

using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat9 = Eigen::Matrix<double, 9, 9>;

// The 9 non-constant monomials of eq. (4.1) (x², y², z², xy, yz, zx, x, y, z) and their gradients.
Vec9 monomials(const Eigen::Vector3d& p) {
  Vec9 m;
  m << p.x() * p.x(), p.y() * p.y(), p.z() * p.z(), p.x() * p.y(), p.y() * p.z(), p.z() * p.x(),
      p.x(), p.y(), p.z();
  return m;
}

Eigen::Matrix<double, 3, 9> gradients(const Eigen::Vector3d& p) {
  Eigen::Matrix<double, 3, 9> J;
  J << 2 * p.x(), 0, 0, p.y(), 0, p.z(), 1, 0, 0,  //
      0, 2 * p.y(), 0, p.x(), p.z(), 0, 0, 1, 0,   //
      0, 0, 2 * p.z(), 0, p.y(), p.x(), 0, 0, 1;
  return J;
}

struct Moments {
  Vec9 m = Vec9::Zero();
  Mat9 mm = Mat9::Zero(), jj = Mat9::Zero();
};

}  // namespace

// Bae 2002, eq. (4.1) fitted in the least-squares sense with Taubin's normalisation.
QuadricFit fit_quadric(const Eigen::Matrix3Xd& points, const QuadricFitOptions& options) {
  const Eigen::Index n = points.cols();
  if (n < 9) throw InputError("quadric fit: " + std::to_string(n) + " points, expected at least 9");
  if (!points.allFinite()) throw InputError("quadric fit: a point is not finite");
  QuadricFit out;
  out.centroid = points.rowwise().mean();
  out.scale = std::sqrt((points.colwise() - out.centroid).colwise().squaredNorm().mean());
  if (!(out.scale > 0.0)) throw InputError("quadric fit: all points coincide");
  const Eigen::Vector3d c = out.centroid;
  const double s = out.scale;

  const int chunks = worker_count(options.threads, static_cast<std::size_t>(n));
  std::vector<Moments> part(static_cast<std::size_t>(chunks));
  parallel_chunks(static_cast<std::size_t>(n), chunks, [&](std::size_t b, std::size_t e, int k) {
    Moments& M = part[static_cast<std::size_t>(k)];
    for (std::size_t i = b; i < e; ++i) {
      const Eigen::Vector3d p = (points.col(static_cast<Eigen::Index>(i)) - c) / s;
      const Vec9 m = monomials(p);
      const Eigen::Matrix<double, 3, 9> J = gradients(p);
      M.m += m;
      M.mm.selfadjointView<Eigen::Lower>().rankUpdate(m);
      M.jj.noalias() += J.transpose() * J;
    }
  });
  Moments M;
  for (const Moments& p : part) M.m += p.m, M.mm += p.mm, M.jj += p.jj;
  const Vec9 mean = M.m / static_cast<double>(n);
  // The constant q10 = −a·mean eliminated: the covariance of the monomials against Taubin's N.
  const Mat9 C = Mat9(M.mm.selfadjointView<Eigen::Lower>()) / static_cast<double>(n) - mean * mean.transpose();
  const Mat9 N = M.jj / static_cast<double>(n);
  Eigen::GeneralizedSelfAdjointEigenSolver<Mat9> ges(C, N);
  if (ges.info() != Eigen::Success)
    throw InputError("quadric fit: the points span no surface (degenerate moments)");
  const Vec9 a = ges.eigenvectors().col(0);
  Quadric local;
  local.q.head<9>() = a;
  local.q[9] = -a.dot(mean);
  local.q /= local.q.norm();

  // Sampson distances |q|/|∇q| in the normalised coordinates.
  double sum2 = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d p = (points.col(i) - c) / s;
    const double g = local.gradient(p).norm();
    const double r = g > 0.0 ? local(p) / g : 0.0;
    sum2 += r * r;
  }
  const double rms = std::sqrt(sum2 / static_cast<double>(n));
  out.rms_distance = rms * s;
  const double tol = options.rank_tolerance > 0.0 ? options.rank_tolerance : std::max(1e-6, 3.0 * rms);
  out.classification = classify_quadric(local, 1.0, tol);
  out.normalized = local;
  // Back to the input coordinates: y = (x − c)/s, i.e. y = A x + t with A = I/s, t = −c/s.
  out.quadric = local.substituted(Eigen::Matrix3d::Identity() / s, -c / s);
  out.quadric.q /= out.quadric.q.norm();
  return out;
}

}  // namespace polarform
