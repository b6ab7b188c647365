#include "src/fit/meridian_function.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "src/error.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/knots.h"

namespace polarform {

namespace {

constexpr int kDegree = 3;

}  // namespace

// NURBS Book §9.4.1 (least-squares curve approximation) on uniform knots, a second-difference
// ridge of relative weight 1e-9 for spans without data.
MeridianFunction fit_meridian_function(const Eigen::Matrix2Xd& zr, int size) {
  const Eigen::Index n = zr.cols();
  size = std::max(size, kDegree + 1);
  if (n < size)
    throw InputError("meridian profile: " + std::to_string(n) + " points for " +
                     std::to_string(size) + " coefficients");
  double z0 = zr.row(0).minCoeff(), z1 = zr.row(0).maxCoeff();
  if (!(z1 > z0)) z1 = z0 + 1.0;
  const Knots knots = uniform_clamped_knots(kDegree, size - kDegree, z0, z1);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(size, size);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(size);
  double N[kDegree + 1];
  for (Eigen::Index k = 0; k < n; ++k) {
    const double z = zr(0, k);
    const int span = find_span(kDegree, knots, size, z);
    basis_funs(span, z, kDegree, knots, N);
    const int first = span - kDegree;
    for (int i = 0; i <= kDegree; ++i) {
      b[first + i] += N[i] * zr(1, k);
      for (int j = 0; j <= kDegree; ++j) A(first + i, first + j) += N[i] * N[j];
    }
  }
  const double ridge = 1e-9 * std::max(A.diagonal().mean(), 1e-300);
  for (int i = 0; i + 2 < size; ++i) {
    const double d[3] = {1.0, -2.0, 1.0};
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) A(i + a, i + c) += ridge * d[a] * d[c];
  }
  A.diagonal().array() += 1e-14 * A.diagonal().mean();
  const Eigen::VectorXd coef = A.ldlt().solve(b);
  MeridianFunction p;
  p.r = BSplineFunction(kDegree, knots, coef);
  double rss = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    const double e = zr(1, k) - p.r(zr(0, k));
    rss += e * e;
  }
  p.rms = std::sqrt(rss / double(n));
  const double fill = 1.0 - double(size) / double(n);
  p.gcv = (rss / double(n)) / (fill * fill);
  return p;
}

// Craven & Wahba 1979: GCV = (RSS/n) / (1 − m/n)².
int choose_meridian_function_size(const Eigen::Matrix2Xd& zr, int max_size) {
  const int limit = std::min<Eigen::Index>(max_size, zr.cols() / 4);
  int size = 6, best = std::min(6, std::max(limit, kDegree + 1));
  if (limit <= 6) return best;
  double best_gcv = fit_meridian_function(zr, size).gcv;
  int misses = 0;
  while (misses < 2) {
    const int next = std::min(limit, std::max(size + 1, size * 3 / 2));
    if (next == size) break;
    size = next;
    const double g = fit_meridian_function(zr, size).gcv;
    if (g < (1.0 - 0.01) * best_gcv) {
      best_gcv = g, best = size, misses = 0;
    } else {
      ++misses;
      if (g < best_gcv) best_gcv = g, best = size;
    }
  }
  return best;
}

MeridianModel meridian_function_model(int size) {
  return [size](const Eigen::Matrix2Xd& zr) {
    const MeridianFunction p = fit_meridian_function(zr, size);
    const BSplineFunction slope = p.r.derivative();
    MeridianResiduals out;
    out.distance.resize(zr.cols());
    out.normal.resize(2, zr.cols());
    out.valid.assign(static_cast<std::size_t>(zr.cols()), 1);
    for (Eigen::Index k = 0; k < zr.cols(); ++k) {
      const double f = p.r(zr(0, k)), df = slope(zr(0, k));
      const double c = 1.0 / std::sqrt(1.0 + df * df);
      out.distance[k] = (zr(1, k) - f) * c;
      out.normal.col(k) << -df * c, c;
    }
    return out;
  };
}

}  // namespace polarform
