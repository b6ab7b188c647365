#include "src/fit/meridian_function.h"

#include <algorithm>
#include <cmath>

#include "src/error.h"
#include "src/fit/function_fit.h"

namespace polarform {

namespace {

constexpr int kDegree = 3;

}  // namespace

// The 1 x n least-squares function fit of function_fit.h (uniform knots, relative fairing for
// spans without data) with a fixed size, scored by GCV.
MeridianFunction fit_meridian_function(const Eigen::Matrix2Xd& zr, int size) {
  const Eigen::Index n = zr.cols();
  size = std::max(size, kDegree + 1);
  if (n < size)
    throw InputError("meridian profile: " + std::to_string(n) + " points for " +
                     std::to_string(size) + " coefficients");
  double z0 = zr.row(0).minCoeff(), z1 = zr.row(0).maxCoeff();
  if (!(z1 > z0)) z1 = z0 + 1.0;
  FunctionFitOptions o;
  o.degree_v = kDegree;
  o.size_v = size;
  o.reduce_constant = false;
  o.threads = 1;
  const CurveFunctionFit f =
      fit_curve_function(zr.row(0).transpose(), zr.row(1).transpose(), z0, z1, false, o);
  MeridianFunction p;
  p.r = f.F;
  const double rss = f.errors.squaredNorm();
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
