#include "designers/convert/sisl_peer.h"

#include <sisl.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/error.h"
#include "src/nurbs/bspline.h"
#include "src/nurbs/periodic.h"

namespace polarform {

namespace {

struct FreeCurve {
  void operator()(SISLCurve* c) const { freeCurve(c); }
};
using CurvePtr = std::unique_ptr<SISLCurve, FreeCurve>;

// The SISL curve as a clamped NurbsCurve2d: its period [et[ik-1], et[in]] (the whole curve when
// open) clipped out by knot insertion, the parameter mapped linearly onto [R.start, R.end] so that
// it approximates the polar angle, as the measurement wants.
NurbsCurve2d to_nurbs(const SISLCurve& c, const PolarFunction& R) {
  const int p = c.ik - 1;
  const double u0 = c.et[p], u1 = c.et[c.in];
  const double scale = (R.end - R.start) / (u1 - u0);
  Knots knots;
  for (int i = 0; i < c.in + c.ik; ++i) knots.push_back(R.start + (c.et[i] - u0) * scale);
  Eigen::MatrixXd coefs(2, c.in);
  for (int i = 0; i < c.in; ++i) coefs.col(i) << c.ecoef[2 * i], c.ecoef[2 * i + 1];
  const BSpline clamped = clip(BSpline(p, std::move(knots), std::move(coefs)), R.start, R.end);
  NurbsCurve2d::Points points;
  for (int i = 0; i < clamped.size(); ++i) points.emplace_back(clamped.coefs().col(i));
  return NurbsCurve2d(p, clamped.knots(), points, {});
}

// The fit at one eeps to the samples (x0, y0, x1, ...), or nothing if s1961 reports an error.
std::optional<NurbsCurve2d> fit(const std::vector<double>& samples, const PolarFunction& R,
                                int degree, double eeps, const S1961Options& options) {
  std::vector<double> flat = samples;  // s1961 takes a non-const array: each call its own copy
  const int im = static_cast<int>(flat.size() / 2);
  std::vector<double> epar;  // θ, for parametrization 3
  if (options.parametrization == 3)
    for (int k = 0; k < im; ++k)
      epar.push_back(k == im - 1 ? R.end : R.start + (R.end - R.start) * k / (im - 1));
  else
    epar.assign(im, 0.0);
  double tolerance[2] = {eeps, eeps};
  double emxerr[2] = {0.0, 0.0};
  const bool closed = R.closed();
  const int ends = closed ? 0 : 1;
  SISLCurve* raw = nullptr;
  int jstat = 0;
  s1961(flat.data(), im, 2, options.parametrization, epar.data(), tolerance, ends, ends,
        closed ? -1 : 1, options.linear_share, options.iterations, degree + 1, &raw, emxerr,
        &jstat);
  const CurvePtr curve(raw);
  if (jstat < 0 || !curve || curve->in < curve->ik) return std::nullopt;
  try {
    return to_nurbs(*curve, R);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// How far the polygon of `count` samples lies from the contour: the largest distance from a chord's
// midpoint to the contour point at the middle angle.
double polygon_deviation(const PolarFunction& R, int count) {
  const std::vector<Eigen::Vector2d> q = peer_contour_samples(R, count);
  double worst = 0.0;
  for (int k = 0; k + 1 < count; ++k) {
    const double t = R.start + (R.end - R.start) * (k + 0.5) / (count - 1);
    const Eigen::Vector2d mid = R(t) * Eigen::Vector2d(std::cos(t), std::sin(t));
    worst = std::max(worst, (mid - 0.5 * (q[k] + q[k + 1])).norm());
  }
  return worst;
}

// The samples for s1961 at tolerance tol: kPeerSamples, multiplied (the deviation falls with the
// square of the spacing) until the polygon lies within tol/10 of the contour, at most 10-fold; 0
// when even the 10-fold polygon lies more than tol/2 from the contour (no fit would verify).
int sample_count(const PolarFunction& R, double tol) {
  constexpr int kMaxFactor = 10;
  const int spans = kPeerSamples - 1;
  const double deviation = polygon_deviation(R, kPeerSamples);
  if (deviation / (kMaxFactor * kMaxFactor) > 0.5 * tol) return 0;
  const double factor = std::ceil(std::sqrt(deviation / (0.1 * tol)));
  return spans * std::clamp(static_cast<int>(factor), 1, kMaxFactor) + 1;
}

}  // namespace

// Peer baseline of issue 14: SISL s1961 (Lyche–Mørken knot removal on the piecewise linear
// interpolant).
PeerCurve sisl_s1961(const PolarFunction& R, int degree, double tol, const S1961Options& options) {
  if (degree < 1 || degree > 20)
    throw InputError("sisl_s1961: degree " + std::to_string(degree) + " outside [1, 20]");
  if (!(tol > 0)) throw InputError("sisl_s1961: tolerance must be > 0 mm");
  std::vector<double> flat;
  const int count = options.samples > 0 ? options.samples : sample_count(R, tol);
  if (count == 0) return {};
  for (const Eigen::Vector2d& q : peer_contour_samples(R, count)) {
    flat.push_back(q.x());
    flat.push_back(q.y());
  }
  return verified_on_ladder(R, tol,
                            [&](double eeps) { return fit(flat, R, degree, eeps, options); });
}

// Issue 14's best SISL fit: s1961 over a range of orders, the fewest control points kept.
PeerCurve sisl_s1961_best(const PolarFunction& R, int deg_min, int deg_max, double tol) {
  PeerCurve best;
  for (int degree = deg_min; degree <= deg_max; ++degree) {
    PeerCurve c = sisl_s1961(R, degree, tol);
    if (c.found && (!best.found || c.control_points < best.control_points)) best = std::move(c);
  }
  return best;
}

}  // namespace polarform
