#include "src/nurbs/spine_curvature_scan.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "src/nurbs/brent_minimum.h"

namespace polarform {

namespace {

// The non-empty knot spans [a, b] of the domain.
std::vector<std::pair<double, double>> domain_spans(const NurbsCurve3d& spine) {
  std::vector<std::pair<double, double>> spans;
  const auto bps = breakpoints(spine.knots());
  for (std::size_t k = 1; k < bps.size(); ++k)
    if (bps[k - 1].value >= spine.front() && bps[k].value <= spine.back())
      spans.emplace_back(bps[k - 1].value, bps[k].value);
  return spans;
}

}  // namespace

double spine_curvature(const NurbsCurve3d& spine, double t) {
  const auto d = spine.derivatives(t, 2);
  const double speed = d[1].norm();
  return d[1].cross(d[2]).norm() / (speed * speed * speed);
}

SpineCurvature scan_max_curvature(const NurbsCurve3d& spine) {
  SpineCurvature best{0.0, spine.front()};
  const auto kappa = [&](double t) { return spine_curvature(spine, t); };
  const int samples = 16 * (spine.degree() + 1);
  for (const auto& [a, b] : domain_spans(spine)) {
    const double b_inside = std::nextafter(b, a);  // the span's own one-sided end
    std::vector<double> t(samples + 1), k(samples + 1);
    for (int i = 0; i <= samples; ++i) {
      t[i] = i == samples ? b_inside : a + (b - a) * i / samples;
      k[i] = kappa(t[i]);
    }
    for (int i = 0; i <= samples; ++i) {
      const bool left_ok = i == 0 || k[i] >= k[i - 1], right_ok = i == samples || k[i] >= k[i + 1];
      if (!left_ok || !right_ok) continue;
      SpineCurvature c{k[i], t[i]};
      const Minimum m = brent_minimum([&](double u) { return -kappa(u); }, t[std::max(i - 1, 0)],
                                      t[std::min(i + 1, samples)]);
      if (-m.value > c.kappa_max) c = {-m.value, m.x};
      if (c.kappa_max > best.kappa_max) best = c;
    }
  }
  return best;
}

}  // namespace polarform
