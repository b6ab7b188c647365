// max_curvature of pipe_surface.h: the largest curvature of a spine, MIT 13.472J (8.46), piece by
// piece over its Bézier decomposition — exactly on integral pieces (the roots of (κ²)′, Cho et al.
// for integral Bézier curves), by a grid and golden-section refinement on rational ones.
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "src/nurbs/bernstein_roots.h"
#include "src/nurbs/bezier.h"
#include "src/nurbs/pipe_surface.h"

namespace polarform {

namespace {

using Poly = std::vector<double>;  // power basis in the piece's own t ∈ [0, 1]

// Power-basis coefficients of the polynomial with Bernstein coefficients b.
Poly bernstein_to_power(const Eigen::VectorXd& b) {
  const int n = static_cast<int>(b.size()) - 1;
  Poly power(static_cast<std::size_t>(n + 1), 0.0);
  // B_i^n(t) = C(n, i) t^i (1 − t)^(n−i) = Σ_j C(n, i) C(n − i, j) (−1)^j t^(i+j).
  for (int i = 0; i <= n; ++i) {
    double cni = 1;
    for (int k = 1; k <= i; ++k) cni = cni * (n - k + 1) / k;
    double c = 1;
    for (int j = 0; i + j <= n; ++j) {
      power[static_cast<std::size_t>(i + j)] += b(i) * cni * c * (j % 2 ? -1 : 1);
      c = c * (n - i - j) / (j + 1);
    }
  }
  return power;
}

Poly derivative(const Poly& p) {
  Poly d;
  for (std::size_t k = 1; k < p.size(); ++k) d.push_back(static_cast<double>(k) * p[k]);
  if (d.empty()) d.push_back(0.0);
  return d;
}

Poly product(const Poly& a, const Poly& b) {
  Poly c(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) c[i + j] += a[i] * b[j];
  return c;
}

Poly combine(const Poly& a, double sa, const Poly& b, double sb) {
  Poly c(std::max(a.size(), b.size()), 0.0);
  for (std::size_t k = 0; k < a.size(); ++k) c[k] += sa * a[k];
  for (std::size_t k = 0; k < b.size(); ++k) c[k] += sb * b[k];
  return c;
}

double evaluate(const Poly& p, double t) {
  double v = 0;
  for (std::size_t k = p.size(); k-- > 0;) v = v * t + p[k];
  return v;
}

// κ² = N/S³ with N = |C′ × C″|², S = |C′|² on an integral piece; W = N′S − 3NS′ has the sign of
// (κ²)′ (MIT (8.46) differentiated).
struct IntegralPiece {
  Poly N, S, W;
  explicit IntegralPiece(const Eigen::MatrixXd& h) {
    std::array<Poly, 3> d1, d2;
    for (int k = 0; k < 3; ++k) {
      d1[k] = derivative(bernstein_to_power(h.row(k).transpose() / h(3, 0)));
      d2[k] = derivative(d1[k]);
    }
    S = product(d1[0], d1[0]);
    for (int k = 1; k < 3; ++k) S = combine(S, 1, product(d1[k], d1[k]), 1);
    N = {0.0};
    for (int k = 0; k < 3; ++k) {
      const int a = (k + 1) % 3, b = (k + 2) % 3;
      const Poly c = combine(product(d1[a], d2[b]), 1, product(d1[b], d2[a]), -1);
      N = combine(N, 1, product(c, c), 1);
    }
    W = combine(product(derivative(N), S), 1, product(N, derivative(S)), -3);
  }
  double kappa(double t) const {
    const double s = evaluate(S, t);
    return std::sqrt(std::max(0.0, evaluate(N, t)) / (s * s * s));
  }
};

// The root of W in [lo, hi] by bisection where W changes sign there, else the middle.
double refine_root(const Poly& W, double lo, double hi) {
  const double f_lo = evaluate(W, lo);
  if (f_lo * evaluate(W, hi) > 0) return 0.5 * (lo + hi);
  for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
    const double m = 0.5 * (lo + hi);
    ((evaluate(W, m) > 0) == (f_lo > 0) ? lo : hi) = m;
  }
  return 0.5 * (lo + hi);
}

// κ = |C′ × C″| / |C′|³ of a rational piece at t (MIT (8.46)).
double rational_kappa(const NurbsCurve3d& piece, double t) {
  const auto d = piece.derivatives(t, 2);
  const double s = d[1].norm();
  return d[1].cross(d[2]).norm() / (s * s * s);
}

// Golden-section search for the largest κ in [a, b] (Kiefer 1953).
double golden_max(const NurbsCurve3d& piece, double a, double b) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = rational_kappa(piece, c), fd = rational_kappa(piece, d);
  while (b - a > 1e-12) {
    if (fc > fd) {
      b = d, d = c, fd = fc;
      c = b - g * (b - a), fc = rational_kappa(piece, c);
    } else {
      a = c, c = d, fc = fd;
      d = a + g * (b - a), fd = rational_kappa(piece, d);
    }
  }
  return 0.5 * (a + b);
}

}  // namespace

// MIT 13.472J (8.46): κ_max over the Bézier pieces, with one-sided values at the breaks and
// infinity at a corner (a break where the unit tangent jumps by more than 1e-9 rad).
SpineCurvature max_curvature(const NurbsCurve3d& spine) {
  const BezierSegments bz = decompose_bezier(spine.homogeneous());
  SpineCurvature best{-1.0, spine.front()};
  const auto consider = [&](double kappa, double t) {
    if (kappa > best.kappa_max) best = {kappa, t};
  };
  Eigen::Vector3d previous_end = Eigen::Vector3d::Zero();  // unit tangent at the previous end
  for (std::size_t i = 0; i < bz.segments.size(); ++i) {
    const Eigen::MatrixXd& h = bz.segments[i];
    const double a = bz.breaks[i], span = bz.breaks[i + 1] - a;
    Knots knots(static_cast<std::size_t>(bz.degree + 1), 0.0);
    knots.insert(knots.end(), static_cast<std::size_t>(bz.degree + 1), 1.0);
    const NurbsCurve3d piece(BSpline(bz.degree, std::move(knots), h));
    const Eigen::Vector3d start = piece.derivatives(0.0, 1)[1].normalized();
    if (i > 0 && !(start.cross(previous_end).norm() <= 1e-9 && start.dot(previous_end) > 0))
      consider(std::numeric_limits<double>::infinity(), a);  // a corner: κ is unbounded there
    previous_end = piece.derivatives(1.0, 1)[1].normalized();
    if (bz.degree < 2) {
      consider(0.0, a);
      continue;
    }
    if ((h.row(3).array() == h(3, 0)).all()) {
      const IntegralPiece piece(h);
      consider(piece.kappa(0.0), a);
      consider(piece.kappa(1.0), a + span);
      for (const auto& [lo, hi] : isolate_roots(power_to_bernstein(piece.W))) {
        const double t = refine_root(piece.W, lo, hi);
        consider(piece.kappa(t), a + span * t);
      }
      continue;
    }
    constexpr int grid = 256;
    std::vector<double> k(grid + 1);
    for (int s = 0; s <= grid; ++s) k[s] = rational_kappa(piece, static_cast<double>(s) / grid);
    consider(k[0], a);
    consider(k[grid], a + span);
    for (int s = 1; s < grid; ++s)
      if (k[s] >= k[s - 1] && k[s] >= k[s + 1]) {
        const double t = golden_max(piece, (s - 1.0) / grid, (s + 1.0) / grid);
        consider(rational_kappa(piece, t), a + span * t);
      }
  }
  return best;
}

}  // namespace polarform
