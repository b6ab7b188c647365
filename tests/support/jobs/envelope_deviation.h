// Measuring a roller cam's curve against an independent path of roller centres: every curve point's
// distance to the nearest centre minus the roller radius (nearest by a window around the previous
// point's, refined by a ternary search on θ), and every 10th centre's distance to the curve points
// (so that the curve covers the whole envelope). Shared by the oscillating, grooved and conjugate
// cam-job tests; the centre paths come from plain trigonometry (arm_oracle.h, the tests' own). And
// the height a roller rests at on an exported curve (roller_height), the conjugate tests' check.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
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

// The height on the follower axis x = e of a roller of radius r resting on the curve (from above,
// side +1) or hanging under it (side -1) at cam angle θ: the extreme over the curve's points in
// the fixed frame of y ± sqrt(r² − (x − e)²), the best of `samples` refined by golden-section
// search on the curve's parameter.
inline double roller_height(const NurbsCurve2d& c, double theta, int sigma, double e, double r,
                            int side, int samples = 8000) {
  const Eigen::Rotation2Dd turn(sigma * theta);  // cam frame to fixed frame
  const auto height = [&](double u) {
    const Eigen::Vector2d x = turn * c.point(u);
    const double dx = x.x() - e;
    return std::abs(dx) < r ? side * (x.y() + side * std::sqrt(r * r - dx * dx)) : -1e300;
  };
  const double a = c.front(), h = (c.back() - a) / samples;
  int best = 0;
  for (int i = 1; i < samples; ++i)
    if (height(a + i * h) > height(a + best * h)) best = i;
  double lo = a + (best - 1) * h, hi = a + (best + 1) * h;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 60; ++it) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    (height(m1) > height(m2) ? hi : lo) = height(m1) > height(m2) ? m2 : m1;
  }
  return side * std::max(height(0.5 * (lo + hi)), height(a + best * h));
}

}  // namespace polarform::test
