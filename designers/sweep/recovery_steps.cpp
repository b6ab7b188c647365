// Input checks, stage timing and strided subsets for the sweep recoveries.
#include "designers/sweep/recovery_steps.h"

#include <algorithm>
#include <cmath>

#include "src/error.h"

namespace polarform {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

Eigen::Matrix2Xd kept_columns(const Eigen::Matrix2Xd& P, const std::vector<char>& flags) {
  if (flags.empty()) return P;
  Eigen::Matrix2Xd out(2, std::count(flags.begin(), flags.end(), 1));
  Eigen::Index j = 0;
  for (Eigen::Index k = 0; k < P.cols(); ++k)
    if (flags[static_cast<std::size_t>(k)]) out.col(j++) = P.col(k);
  return out;
}

Eigen::Matrix3Xd strided(const Eigen::Matrix3Xd& P, int max_points) {
  const Eigen::Index stride = std::max<Eigen::Index>(1, (P.cols() + max_points - 1) / max_points);
  Eigen::Matrix3Xd sub(3, (P.cols() + stride - 1) / stride);
  for (Eigen::Index k = 0; k < sub.cols(); ++k) sub.col(k) = P.col(k * stride);
  return sub;
}

void check_sweep_input(const Eigen::Matrix3Xd& points,
                       const std::optional<Eigen::Vector3d>& direction, const std::string& what) {
  if (points.cols() < 8)
    throw InputError(what + ": " + std::to_string(points.cols()) + " points, need at least 8");
  if (!points.allFinite()) throw InputError(what + ": a point has a non-finite coordinate");
  if (direction && !(direction->norm() > 0.0))
    throw InputError(what + ": the " + (what.starts_with("revolution") ? "axis " : "") +
                     "direction is zero");
}

void measure_point_errors(SweptFit& fit, int threads) {
  fit.distances = meridian_distances(fit.profile, fit.plane, threads).distance;
  fit.error = error_stats(fit.distances);
  fit.unexplained = 0;
  for (Eigen::Index k = 0; k < fit.distances.size(); ++k)
    fit.unexplained += std::abs(fit.distances[k]) > fit.tolerance;
}

}  // namespace polarform
