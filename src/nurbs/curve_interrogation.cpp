#include "src/nurbs/curve_interrogation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/nurbs/bernstein_roots.h"
#include "src/nurbs/bezier.h"

namespace polarform {

namespace {

// One Bézier segment as a curve on its own interval: evaluated at its ends, it gives the
// one-sided derivatives of the whole curve there.
NurbsCurve2d segment_curve(const BezierSegments& b, std::size_t i) {
  const int p = b.degree;
  Knots knots(static_cast<std::size_t>(p + 1), b.breaks[i]);
  knots.insert(knots.end(), static_cast<std::size_t>(p + 1), b.breaks[i + 1]);
  return NurbsCurve2d(BSpline(p, std::move(knots), b.segments[i]));
}

// Power-basis coefficients (in t on [0, 1]) of the polynomial with Bernstein coefficients b.
std::vector<double> bernstein_to_power(const Eigen::VectorXd& b) {
  const int n = static_cast<int>(b.size()) - 1;
  std::vector<double> power(static_cast<std::size_t>(n + 1), 0.0);
  // B_i^n(t) = C(n, i) t^i (1 − t)^(n−i) = sum_j C(n, i) C(n − i, j) (−1)^j t^(i+j).
  for (int i = 0; i <= n; ++i) {
    double cni = 1;
    for (int k = 1; k <= i; ++k) cni = cni * (n - k + 1) / k;
    double c = 1;  // C(n − i, j)
    for (int j = 0; i + j <= n; ++j) {
      power[static_cast<std::size_t>(i + j)] += b(i) * cni * c * (j % 2 ? -1 : 1);
      c = c * (n - i - j) / (j + 1);
    }
  }
  return power;
}

std::vector<double> derivative(const std::vector<double>& p) {
  std::vector<double> d;
  for (std::size_t k = 1; k < p.size(); ++k) d.push_back(static_cast<double>(k) * p[k]);
  if (d.empty()) d.push_back(0.0);
  return d;
}

std::vector<double> product(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> c(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}

void add(std::vector<double>& into, const std::vector<double>& p, double sign) {
  if (into.size() < p.size()) into.resize(p.size(), 0.0);
  for (std::size_t k = 0; k < p.size(); ++k) into[k] += sign * p[k];
}

double evaluate(const std::vector<double>& p, double t) {
  double v = 0;
  for (std::size_t k = p.size(); k-- > 0;) v = v * t + p[k];
  return v;
}

}  // namespace

std::vector<KnotJump> derivative_jumps(const NurbsCurve2d& curve, int k) {
  if (k < 1 || k > curve.degree())
    throw InputError("derivative jumps: order " + std::to_string(k) + " outside [1, degree " +
                     std::to_string(curve.degree()) + "]");
  const BezierSegments b = decompose_bezier(curve.homogeneous());
  std::vector<KnotJump> out;
  for (std::size_t i = 1; i < b.segments.size(); ++i) {
    const double u = b.breaks[i];
    const auto left = segment_curve(b, i - 1).derivatives(u, k);
    const auto right = segment_curve(b, i).derivatives(u, k);
    out.push_back(
        {u, (right[static_cast<std::size_t>(k)] - left[static_cast<std::size_t>(k)]).norm()});
  }
  return out;
}

double signed_curvature(const NurbsCurve2d& curve, double u) {
  const auto d = curve.derivatives(u, 2);
  const double speed = d[1].norm();
  return (d[1].x() * d[2].y() - d[1].y() * d[2].x()) / (speed * speed * speed);
}

double curvature_derivative(const NurbsCurve2d& curve, double u) {
  const auto d = curve.derivatives(u, 3);
  const double cross2 = d[1].x() * d[2].y() - d[1].y() * d[2].x();
  const double cross3 = d[1].x() * d[3].y() - d[1].y() * d[3].x();
  const double speed2 = d[1].squaredNorm(), speed = std::sqrt(speed2);
  return (cross3 * speed2 - 3 * cross2 * d[1].dot(d[2])) / (speed2 * speed2 * speed);
}

// Per segment, D(t) = det(Pʷ, Pʷ′, Pʷ″) in t in [0, 1] has the sign of the curvature (w > 0).
std::vector<double> inflections(const NurbsCurve2d& curve) {
  const BezierSegments b = decompose_bezier(curve.homogeneous());
  std::vector<double> out;
  double previous_end = 0.0;  // D of the previous segment at its end (its sign)
  for (std::size_t i = 0; i < b.segments.size(); ++i) {
    std::vector<double> X = bernstein_to_power(b.segments[i].row(0).transpose());
    std::vector<double> Y = bernstein_to_power(b.segments[i].row(1).transpose());
    std::vector<double> W = bernstein_to_power(b.segments[i].row(2).transpose());
    const std::vector<double> X1 = derivative(X), Y1 = derivative(Y), W1 = derivative(W);
    const std::vector<double> X2 = derivative(X1), Y2 = derivative(Y1), W2 = derivative(W1);
    // det [X X′ X″; Y Y′ Y″; W W′ W″] by the first column.
    std::vector<double> D;
    add(D, product(X, product(Y1, W2)), 1);
    add(D, product(X, product(Y2, W1)), -1);
    add(D, product(Y, product(X1, W2)), -1);
    add(D, product(Y, product(X2, W1)), 1);
    add(D, product(W, product(X1, Y2)), 1);
    add(D, product(W, product(X2, Y1)), -1);
    const double a = b.breaks[i], h = b.breaks[i + 1] - a;
    // The curvature changes sign across the knot itself (a knot of reduced continuity).
    if (i > 0 && previous_end * evaluate(D, 0.0) < 0) out.push_back(a);
    previous_end = evaluate(D, 1.0);
    for (const auto& [t0, t1] : isolate_roots(power_to_bernstein(D))) {
      double lo = t0, hi = t1;
      const double f_lo = evaluate(D, lo), f_hi = evaluate(D, hi);
      if (f_lo * f_hi > 0) continue;  // no sign change: a flat point
      for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
        const double m = 0.5 * (lo + hi);
        ((evaluate(D, m) > 0) == (f_lo > 0) ? lo : hi) = m;
      }
      const double t = 0.5 * (lo + hi);
      // A zero at the curve's own ends (a natural end's κ = 0, rounded) has no side beyond it.
      const bool at_end = (i == 0 && t < 1e-9) || (i + 1 == b.segments.size() && t > 1 - 1e-9);
      if (t > 0 && t < 1 && !at_end) out.push_back(a + h * t);
    }
  }
  return out;
}

}  // namespace polarform
