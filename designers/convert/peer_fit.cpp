#include "designers/convert/peer_fit.h"

#include <cmath>

#include "designers/convert/conversion_error.h"

namespace polarform {

namespace {
constexpr int kMeasureSamples = 20000;
}  // namespace

std::vector<Eigen::Vector2d> peer_contour_samples(const PolarFunction& R, int count) {
  std::vector<Eigen::Vector2d> points;
  points.reserve(count);
  for (int k = 0; k < count; ++k) {
    const double theta = k == count - 1 ? R.end : R.start + (R.end - R.start) * k / (count - 1);
    const double r = R(theta);
    points.emplace_back(r * std::cos(theta), r * std::sin(theta));
  }
  return points;
}

// Issue 14's verification of a peer: polarform's dense measurement (conversion_error.h) of each
// fit.
PeerCurve verified_on_ladder(const PolarFunction& R, double tol,
                             const std::function<std::optional<NurbsCurve2d>(double)>& fit) {
  for (double factor : kPeerToleranceLadder) {
    std::optional<NurbsCurve2d> c = fit(factor * tol);
    if (!c) continue;
    // Measured densely (a peer places its knots for its samples, not for the error between them).
    const double error = profile_error(*c, R, c->front(), c->back(), kMeasureSamples).max_radial;
    if (error <= tol) return {true, c->size(), c->degree(), error, factor * tol, std::move(*c)};
  }
  return {};
}

}  // namespace polarform
