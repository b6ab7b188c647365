#include "src/fit/cell_grid.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace polarform {

CellGrid::CellGrid(const Eigen::VectorXd& s, const Eigen::VectorXd& t, int points_per_cell)
    : surface_(t.size() != 0) {
  const std::size_t n = static_cast<std::size_t>(s.size());
  if (n == 0) {
    start_.assign(2, 0);
    return;
  }
  const double target = std::clamp(static_cast<double>(n) / points_per_cell, 1.0, double(1 << 18));
  const double sr = std::max(s.maxCoeff() - s.minCoeff(), 1e-300);
  s0_ = s.minCoeff();
  if (surface_) {
    const double tr = std::max(t.maxCoeff() - t.minCoeff(), 1e-300);
    t0_ = t.minCoeff();
    ns_ = std::max(1, static_cast<int>(std::lround(std::sqrt(target * sr / tr))));
    nt_ = std::max(1, static_cast<int>(target / ns_));
    ht_ = tr / nt_ * (1 + 1e-12);
  } else {
    ns_ = std::max(1, static_cast<int>(target));
  }
  hs_ = sr / ns_ * (1 + 1e-12);
  auto cell = [&](Eigen::Index k) { return cell_i(s[k]) * nt_ + (surface_ ? cell_j(t[k]) : 0); };
  std::vector<int> cell_of(n);
  start_.assign(static_cast<std::size_t>(cells()) + 1, 0);
  for (std::size_t k = 0; k < n; ++k) {
    cell_of[k] = cell(static_cast<Eigen::Index>(k));
    ++start_[static_cast<std::size_t>(cell_of[k]) + 1];
  }
  std::partial_sum(start_.begin(), start_.end(), start_.begin());
  index_.resize(n);
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (std::size_t k = 0; k < n; ++k)
    index_[static_cast<std::size_t>(fill[static_cast<std::size_t>(cell_of[k])]++)] =
        static_cast<int>(k);
}

int CellGrid::cell_i(double s) const {
  return std::clamp(static_cast<int>((s - s0_) / hs_), 0, ns_ - 1);
}

int CellGrid::cell_j(double t) const {
  return std::clamp(static_cast<int>((t - t0_) / ht_), 0, nt_ - 1);
}

}  // namespace polarform
