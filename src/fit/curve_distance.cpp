// True point-to-curve distances: dense samples in a grid index, then Newton polishing.
#include "src/fit/curve_distance.h"

#include <algorithm>
#include <cmath>

#include "src/nurbs/knots.h"

namespace polarform {

template <int Dim>
CurveDistance<Dim>::CurveDistance(const NurbsCurve<Dim>& curve, bool closed, int samples_per_span)
    : curve_(&curve), closed_(closed) {
  const std::vector<Breakpoint> br = breakpoints(curve.knots());
  std::vector<double> us;
  for (std::size_t b = 0; b + 1 < br.size(); ++b) {
    const double a = br[b].value, e = br[b + 1].value;
    if (a < curve.front() || e > curve.back() || !(e > a)) continue;
    for (int s = 0; s < samples_per_span; ++s) us.push_back(a + (e - a) * s / samples_per_span);
  }
  us.push_back(curve.back());
  u_ = Eigen::Map<const Eigen::VectorXd>(us.data(), static_cast<Eigen::Index>(us.size()));
  samples_.resize(Dim, u_.size());
  for (Eigen::Index i = 0; i < u_.size(); ++i) samples_.col(i) = curve.point(u_[i]);
  grid_ = std::make_unique<GridIndex<Dim>>(samples_);
  kinks_.push_back(curve.front());
  for (const Breakpoint& b : br)
    if (b.value > curve.front() && b.value < curve.back() && b.multiplicity >= curve.degree())
      kinks_.push_back(b.value);
  kinks_.push_back(curve.back());
}

// NURBS Book §6.1, eq. (6.3): Newton on f(u) = C'(u)·(C(u) − P) inside [lo, hi] (wrapped for a
// closed curve without kinks).
template <int Dim>
double CurveDistance<Dim>::newton(const Point& p, double u, double lo, double hi) const {
  const bool wrap = closed_ && kinks_.size() == 2;
  // Inside the piece, derivatives at its end kink come from the span on the piece's own side.
  if (hi < curve_->back()) hi -= 1e-13 * (hi - lo);
  u = std::clamp(u, lo + 1e-9 * (hi - lo), hi - 1e-9 * (hi - lo));
  for (int it = 0; it < 16; ++it) {
    const auto d = curve_->derivatives(u, 2);
    const Point r = d[0] - p;
    const double f = d[1].dot(r), df = d[2].dot(r) + d[1].squaredNorm();
    if (!(df > 0.0)) break;
    double next = u - f / df;
    if (wrap) {
      next = lo + std::fmod(next - lo, hi - lo);
      if (next < lo) next += hi - lo;
    } else {
      next = std::clamp(next, lo, hi);
    }
    const double step = std::abs(next - u);
    u = next;
    if (step <= 1e-15 * (hi - lo)) break;
  }
  return u;
}

template <int Dim>
typename CurveDistance<Dim>::Foot CurveDistance<Dim>::project(const Point& p) const {
  const int s = grid_->nearest(p);
  Foot best{u_[s], (samples_.col(s) - p).norm()};
  // The smooth pieces (between kinks) holding the sample: two when it sits on a kink.
  const auto hi = std::upper_bound(kinks_.begin(), kinks_.end(), best.u);
  const double u0 = best.u;
  auto polish = [&](double lo, double up) {
    const double u = newton(p, u0, lo, up);
    const double dist = (curve_->point(u) - p).norm();
    if (dist < best.distance) best = {u, dist};
  };
  if (hi == kinks_.end()) {
    polish(*(hi - 2), *(hi - 1));
  } else {
    polish(*(hi - 1), *hi);
    if (*(hi - 1) == u0 && hi - 1 != kinks_.begin()) polish(*(hi - 2), *(hi - 1));
  }
  return best;
}

template class CurveDistance<2>;
template class CurveDistance<3>;

}  // namespace polarform
