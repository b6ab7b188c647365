#include "designers/convert/profile_table.h"

#include <algorithm>
#include <cmath>
#include <numbers>

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
  nodes_.resize(at_.size());
  // Buckets of the nominal spacing: each holds at most a couple of nodes, so a lookup is a
  // division and a short scan.
  bucket_width_ = step;
  for (int k = 0; k <= intervals; ++k) {
    const double x = start_ + k * step;
    const auto it = std::upper_bound(at_.begin(), at_.end(), x);
    bucket_.push_back(static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - at_.begin() - 1, 0)));
  }
  const double nudge = 1e-9 * (end_ - start_);
  for (std::size_t i = 0; i < at_.size(); ++i) {
    // The domain's ends and R's breakpoints: each side's derivatives from just inside it, taken
    // back to the node along the side's Taylor series.
    if (std::binary_search(fixed.begin(), fixed.end(), at_[i])) {
      Node& n = nodes_[i];
      R.derivatives(std::max(at_[i] - nudge, start_), 2, n.left);
      R.derivatives(std::min(at_[i] + nudge, end_), 2, n.right);
      if (i > 0) n.left[0] += nudge * n.left[1], n.left[1] += nudge * n.left[2];
      if (i + 1 < at_.size()) n.right[0] -= nudge * n.right[1], n.right[1] -= nudge * n.right[2];
    } else {
      R.derivatives(at_[i], 2, nodes_[i].left);
      std::copy(nodes_[i].left, nodes_[i].left + 3, nodes_[i].right);
    }
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

// Quintic Hermite interpolation of value, first and second derivative at both ends.
void ProfileTable::derivatives(double psi, double* out) const {
  psi = wrap(psi);
  const auto k = std::min(static_cast<std::size_t>(std::max((psi - start_) / bucket_width_, 0.0)),
                          bucket_.size() - 1);
  std::size_t i = bucket_[k];
  while (i + 2 < at_.size() && at_[i + 1] <= psi) ++i;
  i = std::min(i, at_.size() - 2);
  const double h = at_[i + 1] - at_[i], t = (psi - at_[i]) / h;
  const double* a = nodes_[i].right;
  const double* b = nodes_[i + 1].left;
  const double t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
  // Basis of the quintic Hermite interpolant on [0, 1] and their derivatives.
  const double h0 = 1 - 10 * t3 + 15 * t4 - 6 * t5, h1 = t - 6 * t3 + 8 * t4 - 3 * t5,
               h2 = 0.5 * (t2 - 3 * t3 + 3 * t4 - t5), h5 = 10 * t3 - 15 * t4 + 6 * t5,
               h4 = -4 * t3 + 7 * t4 - 3 * t5, h3 = 0.5 * (t3 - 2 * t4 + t5);
  const double d0 = -30 * t2 + 60 * t3 - 30 * t4, d1 = 1 - 18 * t2 + 32 * t3 - 15 * t4,
               d2 = 0.5 * (2 * t - 9 * t2 + 12 * t3 - 5 * t4), d5 = 30 * t2 - 60 * t3 + 30 * t4,
               d4 = -12 * t2 + 28 * t3 - 15 * t4, d3 = 0.5 * (3 * t2 - 8 * t3 + 5 * t4);
  out[0] =
      h0 * a[0] + h * h1 * a[1] + h * h * h2 * a[2] + h5 * b[0] + h * h4 * b[1] + h * h * h3 * b[2];
  out[1] = (d0 * a[0] + h * d1 * a[1] + h * h * d2 * a[2] + d5 * b[0] + h * d4 * b[1] +
            h * h * d3 * b[2]) /
           h;
}

}  // namespace polarform
