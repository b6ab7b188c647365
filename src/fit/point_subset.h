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

// Every k-th column so that at most max_columns remain (all of them when there are fewer).
inline Eigen::Matrix3Xd strided_columns(const Eigen::Matrix3Xd& m, Eigen::Index max_columns) {
  if (m.cols() <= max_columns) return m;
  const Eigen::Index stride = (m.cols() + max_columns - 1) / max_columns;
  Eigen::Matrix3Xd out(3, (m.cols() + stride - 1) / stride);
  for (Eigen::Index a = 0; a < out.cols(); ++a) out.col(a) = m.col(a * stride);
  return out;
}

inline Eigen::VectorXd select_entries(const Eigen::VectorXd& x, const std::vector<int>& idx) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(idx.size()));
  for (std::size_t k = 0; k < idx.size(); ++k) out[static_cast<Eigen::Index>(k)] = x[idx[k]];
  return out;
}

}  // namespace polarform
