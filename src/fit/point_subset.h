// The points (columns) and per-point values (entries) at a list of indices, in that order: the
// share a base surface is fitted to, the points a thinning kept.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace polarform {

inline Eigen::Matrix3Xd select_columns(const Eigen::Matrix3Xd& m, const std::vector<int>& idx) {
  Eigen::Matrix3Xd out(3, static_cast<Eigen::Index>(idx.size()));
  for (std::size_t k = 0; k < idx.size(); ++k)
    out.col(static_cast<Eigen::Index>(k)) = m.col(idx[k]);
  return out;
}

inline Eigen::VectorXd select_entries(const Eigen::VectorXd& x, const std::vector<int>& idx) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(idx.size()));
  for (std::size_t k = 0; k < idx.size(); ++k) out[static_cast<Eigen::Index>(k)] = x[idx[k]];
  return out;
}

}  // namespace polarform
