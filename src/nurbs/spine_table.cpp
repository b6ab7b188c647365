#include "src/nurbs/spine_table.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "src/error.h"

namespace polarform {

namespace {

// Gauss–Legendre nodes and weights on [−1, 1], 8 points (Abramowitz & Stegun, Table 25.4).
constexpr std::array<double, 4> kGaussX = {0.1834346424956498, 0.5255324099163290,
                                           0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> kGaussW = {0.3626837833783620, 0.3137066458778873,
                                           0.2223810344533745, 0.1012285362903763};

}  // namespace

SpineTable::SpineTable(const NurbsCurve3d& spine, int min_nodes) : spine_(&spine) {
  Eigen::Vector3d lo = spine.control_point(0), hi = lo;
  for (const auto& p : spine.control_points()) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  extent_ = (hi - lo).norm();
  const std::vector<Breakpoint> bps = breakpoints(spine.knots());
  std::vector<double> spans;  // breakpoints inside the domain
  for (const auto& bp : bps)
    if (bp.value >= spine.front() && bp.value <= spine.back()) spans.push_back(bp.value);
  const int count = static_cast<int>(spans.size()) - 1;
  const int per_span = std::max(4 * (spine.degree() + 1), (min_nodes + count - 1) / count);
  for (int k = 0; k < count; ++k)
    for (int i = 0; i < per_span; ++i)
      t_.push_back(spans[k] + (spans[k + 1] - spans[k]) * i / per_span);
  t_.push_back(spine.back());
  const double domain = spine.back() - spine.front();
  for (double t : t_) {
    const auto d = spine.derivatives(t, 1);
    if (!(d[1].norm() * domain >= 1e-12 * extent_))
      throw InputError("pipe spine: not regular at t = " + std::to_string(t) + " (|C'| = " +
                       std::to_string(d[1].norm()) + "), expected C' != 0 everywhere");
    point_.push_back(d[0]);
    tangent_.push_back(d[1]);
  }
  arc_.assign(1, 0.0);
  for (std::size_t i = 1; i < t_.size(); ++i)
    arc_.push_back(arc_.back() + integral(t_[i - 1], t_[i]));
}

// Gauss–Legendre quadrature of |C′| on [a, b] (inside one node interval, where C is polynomial
// or rational without breaks).
double SpineTable::integral(double a, double b) const {
  const double m = 0.5 * (a + b), h = 0.5 * (b - a);
  double sum = 0.0;
  for (std::size_t k = 0; k < kGaussX.size(); ++k)
    for (const double sign : {-1.0, 1.0})
      sum += kGaussW[k] * spine_->derivatives(m + sign * h * kGaussX[k], 1)[1].norm();
  return sum * h;
}

double SpineTable::arc_length(double t) const {
  t = std::clamp(t, t_.front(), t_.back());
  const auto i =
      std::max<std::ptrdiff_t>(std::upper_bound(t_.begin(), t_.end(), t) - t_.begin() - 1, 0);
  return arc_[i] + integral(t_[i], t);
}

double SpineTable::parameter_at(double s) const {
  if (s <= 0.0) return t_.front();
  if (s >= arc_.back()) return t_.back();
  const auto i = std::upper_bound(arc_.begin(), arc_.end(), s) - arc_.begin() - 1;
  double a = t_[i], b = t_[i + 1];
  for (int it = 0; it < 100 && b - a > 1e-15 * (std::abs(a) + std::abs(b)); ++it) {
    const double m = 0.5 * (a + b);
    (arc_[i] + integral(t_[i], m) < s ? a : b) = m;
  }
  return 0.5 * (a + b);
}

}  // namespace polarform
