#include "src/nurbs/point_inversion.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "src/error.h"
#include "src/nurbs/bernstein_roots.h"

namespace polarform {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// Distinct non-empty knot spans [a, b) of the domain.
std::vector<std::pair<double, double>> spans(const Knots& knots, int degree, int n) {
  std::vector<std::pair<double, double>> out;
  for (int i = degree; i < n; ++i)
    if (knots[i + 1] > knots[i]) out.emplace_back(knots[i], knots[i + 1]);
  return out;
}

// f(u) = C'(u)·(C(u) − P) (half the derivative of the squared distance) and
// f'(u) = |C'|² + C''·(C − P); NURBS Book §6.1, eqs. (6.3)–(6.4).
struct CurveSample {
  double t, f, df, d2;
  double rounding;  // the rounding level of f: 64 ε |C'| (|C| + |P|)
};

template <int D>
CurveSample curve_sample(const NurbsCurve<D>& c, const Eigen::Matrix<double, D, 1>& p, double t) {
  const auto d = c.derivatives(t, 2);
  const Eigen::Matrix<double, D, 1> r = d[0] - p;
  return {t, d[1].dot(r), d[1].squaredNorm() + d[2].dot(r), r.squaredNorm(),
          64.0 * kEps * d[1].norm() * (d[0].norm() + p.norm())};
}

// On the span [a, a + h], with C = A/w and t = (u − a)/h, f·w³·h = N(t) = (A_t w − A w_t)·(A − P w),
// a polynomial of degree 3p − 1. Its power coefficients in t come from the Taylor coefficients
// h^k/k!·d^k/du^k of the homogeneous curve at a.
template <int D>
std::vector<double> stationary_polynomial(const BSpline& h, const Eigen::Matrix<double, D, 1>& p,
                                          double a, double width) {
  const int q = h.degree();
  Eigen::MatrixXd taylor = h.derivatives(a, q);
  double scale = 1.0;  // h^k / k!
  for (int k = 0; k <= q; ++k) {
    taylor.col(k) *= scale;
    scale *= width / (k + 1);
  }
  const auto A = [&](int k) -> Eigen::Matrix<double, D, 1> { return taylor.col(k).template head<D>(); };
  const auto w = [&](int k) { return taylor(D, k); };
  std::vector<Eigen::Matrix<double, D, 1>> G(2 * q, Eigen::Matrix<double, D, 1>::Zero());
  for (int i = 0; i < q; ++i)
    for (int j = 0; j <= q; ++j) G[i + j] += (i + 1) * (A(i + 1) * w(j) - A(j) * w(i + 1));
  std::vector<double> N(3 * q, 0.0);
  for (int i = 0; i < 2 * q; ++i)
    for (int j = 0; j <= q; ++j) N[i + j] += G[i].dot(A(j) - p * w(j));
  return N;
}

// Root of f in [a, b] with f(a) < 0 < f(b), Newton safeguarded by bisection; Numerical Recipes
// §9.4 (rtsafe). The root is a local minimum of the distance (f increases through it).
template <int D>
double safe_newton(const NurbsCurve<D>& c, const Eigen::Matrix<double, D, 1>& p, double a,
                   double b) {
  const double tol = 4.0 * kEps * std::max({std::abs(a), std::abs(b), b - a});
  double x = 0.5 * (a + b), dx_old = b - a, dx = dx_old;
  CurveSample j = curve_sample(c, p, x);
  for (int it = 0; it < 200; ++it) {
    const bool newton_leaves = ((x - b) * j.df - j.f) * ((x - a) * j.df - j.f) > 0.0;
    if (newton_leaves || std::abs(2.0 * j.f) > std::abs(dx_old * j.df)) {
      dx_old = dx;
      dx = 0.5 * (b - a);
      x = a + dx;
    } else {
      dx_old = dx;
      dx = j.f / j.df;
      x -= dx;
    }
    if (std::abs(dx) <= tol) break;
    j = curve_sample(c, p, x);
    (j.f < 0.0 ? a : b) = x;
  }
  return x;
}

}  // namespace

// NURBS Book §6.1 with a robust start: on every knot span the roots of f are isolated exactly
// (Bernstein sign changes of the numerator polynomial, see bernstein_roots.h), and each root
// where f goes from − to + (a local minimum) is refined by safeguarded Newton. Breakpoints and both
// ends are candidates too, so minima at ends, kinks and the seam of a closed curve are found
// without wrapping; a candidate replaces a refined minimum only when it is better by more than
// rounding.
template <int D>
CurveProjection closest_point(const NurbsCurve<D>& c, const Eigen::Matrix<double, D, 1>& p) {
  if (!p.allFinite()) throw InputError("point inversion: the query point is not finite");
  std::vector<double> roots, candidates;
  for (const auto& [a, b] : spans(c.knots(), c.degree(), c.size())) {
    candidates.push_back(a);
    const std::vector<double> N = stationary_polynomial(c.homogeneous(), p, a, b - a);
    for (const auto& [t0, t1] : isolate_roots(power_to_bernstein(N))) {
      // Evaluate inside the span: its right end just left of b (f is one-sided at a knot).
      const double lo = a + (b - a) * t0, hi = t1 < 1.0 ? a + (b - a) * t1 : std::nextafter(b, a);
      const CurveSample s0 = curve_sample(c, p, lo), s1 = curve_sample(c, p, hi);
      if (s0.f < 0.0 && s1.f > 0.0) roots.push_back(safe_newton(c, p, lo, hi));
      // A root on a subdivision point need not bracket in floating point (f there is rounding).
      if (std::abs(s0.f) <= s0.rounding) roots.push_back(lo);
      if (std::abs(s1.f) <= s1.rounding) roots.push_back(hi);
    }
  }
  candidates.push_back(c.back());
  const auto distance2 = [&](double u) { return (c.point(u) - p).squaredNorm(); };
  double best_u = c.front(), best_d2 = std::numeric_limits<double>::infinity();
  for (double u : roots)
    if (const double d2 = distance2(u); d2 < best_d2) best_u = u, best_d2 = d2;
  const double rounding =
      roots.empty() ? 0.0 : 8.0 * kEps * (p.norm() + c.point(best_u).norm()) * std::sqrt(best_d2);
  for (double u : candidates)
    if (const double d2 = distance2(u); d2 < best_d2 - rounding) best_u = u, best_d2 = d2;
  const Eigen::Matrix<double, D, 1> point = c.point(best_u);
  return {best_u, point, (point - p).norm()};
}

template CurveProjection closest_point<2>(const NurbsCurve<2>&, const Eigen::Vector2d&);
template CurveProjection closest_point<3>(const NurbsCurve<3>&, const Eigen::Vector3d&);

}  // namespace polarform
