// Measuring a roller cam's curve against an independent path of roller centres: every curve point's
// distance to the nearest centre minus the roller radius (nearest by a window around the previous
// point's, refined by a ternary search on θ), and every 10th centre's distance to the curve points
// (so that the curve covers the whole envelope). Shared by the oscillating, grooved and conjugate
// cam-job tests; the centre paths come from plain trigonometry (arm_oracle.h, the tests' own).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <functional>
#include <numbers>
#include <vector>

#include "src/nurbs/nurbs_curve.h"

namespace polarform::test {

struct Deviation {
  double outside = 0.0;  // largest distance beyond the exact envelope (into the roller), mm
  double inside = 0.0;   // largest distance inside it (away from the roller), mm
  double worst() const { return std::max(outside, inside); }
};

// centre(θ): the roller centre in the cam frame at cam angle θ; r: the roller radius.
inline Deviation envelope_deviation(const std::function<Eigen::Vector2d(double)>& centre, double r,
                                    const std::vector<Eigen::Vector2d>& curve) {
  constexpr double pi = std::numbers::pi;
  Deviation dev;
  const int n = 7200;
  std::vector<Eigen::Vector2d> centres(n);
  for (int i = 0; i < n; ++i) centres[i] = centre(2 * pi * i / n);
  int near = 0;
  for (int i = 1; i < n; ++i)
    if ((curve[0] - centres[i]).norm() < (curve[0] - centres[near]).norm()) near = i;
  for (const Eigen::Vector2d& x : curve) {
    const int from = near;
    for (int k = -60; k <= 60; ++k) {
      const int i = ((from + k) % n + n) % n;
      if ((x - centres[i]).norm() < (x - centres[near]).norm()) near = i;
    }
    double lo = 2 * pi * (near - 1) / n, hi = 2 * pi * (near + 1) / n;
    const auto distance = [&](double t) { return (x - centre(t)).norm(); };
    for (int it = 0; it < 40; ++it) {  // (2/3)^40 of 1e-3 rad
      const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
      if (distance(a) < distance(b))
        hi = b;
      else
        lo = a;
    }
    const double gap = distance(0.5 * (lo + hi)) - r;
    dev.outside = std::max(dev.outside, -gap), dev.inside = std::max(dev.inside, gap);
  }
  // Nearest by a window around the previous centre's, as both run round the cam in order.
  const int m = static_cast<int>(curve.size()), window = m / 100 + 2;
  int at = 0;
  for (int i = 1; i < m; ++i)
    if ((curve[i] - centres[0]).norm() < (curve[at] - centres[0]).norm()) at = i;
  for (int i = 0; i < n; i += 10) {
    const int from = at;
    for (int k = -window; k <= window; ++k) {
      const int j = ((from + k) % m + m) % m;
      if ((curve[j] - centres[i]).norm() < (curve[at] - centres[i]).norm()) at = j;
    }
    dev.inside = std::max(dev.inside, (curve[at] - centres[i]).norm() - r);
  }
  return dev;
}

// count points at equal parameter steps.
inline std::vector<Eigen::Vector2d> dense_points(const NurbsCurve2d& c, int count) {
  std::vector<Eigen::Vector2d> out;
  const double a = c.front(), b = c.back();
  for (int i = 0; i < count; ++i) out.push_back(c.point(a + (b - a) * i / count));
  return out;
}

}  // namespace polarform::test
