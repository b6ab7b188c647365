#include "src/base/angle_deviation.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace polarform {

namespace {

// Maximum of a unimodal f on [a, b] by golden-section search down to a bracket of `tol`;
// Kiefer 1953 (golden-section search).
template <class F>
double golden_section_max(F f, double a, double b, double tol) {
  const double r = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = b - r * (b - a), x2 = a + r * (b - a);
  double f1 = f(x1), f2 = f(x2);
  while (b - a > tol) {
    if (f1 >= f2) {
      b = x2, x2 = x1, f2 = f1;
      x1 = b - r * (b - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2;
      x2 = a + r * (b - a), f2 = f(x2);
    }
  }
  return std::max(f1, f2);
}

}  // namespace

// Bae 2002, Fig. 5.2/5.3: Δ(η) = ξ(η) − 2φη, ξ from (2.7)/(5.3).
double max_angle_deviation(ArcKind kind, double half_angle, AlphaRule rule) {
  const double alpha = kind == ArcKind::quartic ? quartic_alpha(half_angle, rule) : 1.0;
  auto deviation = [&](double eta) {
    const double xi = kind == ArcKind::quartic ? quartic_arc_angle(half_angle, alpha, eta)
                                               : rqb_arc_angle(half_angle, eta);
    return std::abs(xi - 2.0 * half_angle * eta);
  };
  constexpr int kGrid = 256;
  std::vector<double> d(kGrid + 1);
  for (int i = 0; i <= kGrid; ++i) d[i] = deviation(static_cast<double>(i) / kGrid);
  double best = std::max(d.front(), d.back());
  for (int i = 1; i < kGrid; ++i) {
    if (d[i] < d[i - 1] || d[i] < d[i + 1]) continue;
    const double a = static_cast<double>(i - 1) / kGrid, b = static_cast<double>(i + 1) / kGrid;
    best = std::max({best, d[i], golden_section_max(deviation, a, b, 1e-14)});
  }
  return best;
}

}  // namespace polarform
