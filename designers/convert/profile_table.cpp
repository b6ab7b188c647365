#include "designers/convert/profile_table.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/task_pool.h"

namespace polarform {

ProfileTable::ProfileTable(const PolarFunction& R, int intervals)
    : start_(R.start), end_(R.end), closed_(R.closed()) {
  std::vector<double> fixed{start_};
  for (double b : R.breakpoints)
    if (b > start_ && b < end_) fixed.push_back(b);
  fixed.push_back(end_);
  const double step = (end_ - start_) / intervals;
  for (std::size_t s = 0; s + 1 < fixed.size(); ++s) {
    const int n = std::max(1, static_cast<int>(std::ceil((fixed[s + 1] - fixed[s]) / step)));
    for (int k = 0; k < n; ++k) at_.push_back(fixed[s] + (fixed[s + 1] - fixed[s]) * k / n);
  }
  at_.push_back(end_);
  struct Node {
    double left[3], right[3];  // R, R', R'' from the interval before / after the node
  };
  std::vector<Node> nodes(at_.size());
  // Buckets of the nominal spacing: each holds at most a couple of nodes, so a lookup is a
  // division and a short scan.
  inverse_bucket_width_ = 1 / step;
  for (int k = 0; k <= intervals; ++k) {
    const double x = start_ + k * step;
    const auto it = std::upper_bound(at_.begin(), at_.end(), x);
    bucket_.push_back(static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - at_.begin() - 1, 0)));
  }
  const double nudge = 1e-9 * (end_ - start_);
  const auto evaluate = [&](std::size_t i) {
    // The domain's ends and R's breakpoints: each side's derivatives from just inside it, taken
    // back to the node along the side's Taylor series.
    if (std::binary_search(fixed.begin(), fixed.end(), at_[i])) {
      Node& n = nodes[i];
      R.derivatives(std::max(at_[i] - nudge, start_), 2, n.left);
      R.derivatives(std::min(at_[i] + nudge, end_), 2, n.right);
      if (i > 0) n.left[0] += nudge * n.left[1], n.left[1] += nudge * n.left[2];
      if (i + 1 < at_.size()) n.right[0] -= nudge * n.right[1], n.right[1] -= nudge * n.right[2];
    } else {
      R.derivatives(at_[i], 2, nodes[i].left);
      std::copy(nodes[i].left, nodes[i].left + 3, nodes[i].right);
    }
  };
  // R is costly (a cam contour's envelope): the nodes in chunks, on every core.
  in_parallel(at_.size(), 64, evaluate);
  // The quintic Hermite interpolant of value, first and second derivative at both ends of each
  // interval, in monomials of t: with A_k = h^k R^(k)(at_i+), B_k = h^k R^(k)(at_i+1−), the basis
  // 1 − 10t³ + 15t⁴ − 6t⁵, t − 6t³ + 8t⁴ − 3t⁵, (t² − 3t³ + 3t⁴ − t⁵)/2 for A_0..A_2 and
  // 10t³ − 15t⁴ + 6t⁵, −4t³ + 7t⁴ − 3t⁵, (t³ − 2t⁴ + t⁵)/2 for B_0..B_2.
  for (std::size_t i = 0; i + 1 < at_.size(); ++i) {
    const double h = at_[i + 1] - at_[i];
    const double* r = nodes[i].right;
    const double* l = nodes[i + 1].left;
    const double A0 = r[0], A1 = h * r[1], A2 = h * h * r[2];
    const double B0 = l[0], B1 = h * l[1], B2 = h * h * l[2];
    intervals_.push_back(
        {{A0, A1, 0.5 * A2, -10 * A0 - 6 * A1 - 1.5 * A2 + 10 * B0 - 4 * B1 + 0.5 * B2,
          15 * A0 + 8 * A1 + 1.5 * A2 - 15 * B0 + 7 * B1 - B2,
          -6 * A0 - 3 * A1 - 0.5 * A2 + 6 * B0 - 3 * B1 + 0.5 * B2},
         1 / h});
  }
}

double ProfileTable::wrap(double psi) const {
  if (psi >= start_ && psi <= end_) return psi;
  if (closed_) {
    const double period = 2 * std::numbers::pi;
    psi = start_ + std::fmod(psi - start_, period);
    return psi < start_ ? psi + period : psi;
  }
  return std::clamp(psi, start_, end_);
}

}  // namespace polarform
