// One-dimensional searches used by the cam analyses on top of a sampled grid: refinement of a
// sampled extremum (Brent's method) and bisection of a sign change. They assume the function is
// unimodal / changes sign once inside the bracket.
#pragma once

#include <cmath>

namespace polarform {

struct Extremum {
  double value = 0.0;
  double theta = 0.0;  // rad
};

// Maximum of f on [a, b] by Brent's method — golden section with parabolic steps (Brent,
// Algorithms for Minimization without Derivatives, 1973, ch. 5, procedure fmin) — to a relative
// angle tolerance of sqrt(machine epsilon); the ends are candidates too.
template <class F>
Extremum refine_maximum(F&& f, double a, double b) {
  constexpr double c = 0.3819660112501051;  // (3 - √5)/2
  const double a0 = a, b0 = b;
  double x = a + c * (b - a), w = x, v = x, d = 0.0, e = 0.0;
  double fx = -f(x), fw = fx, fv = fx;  // minimise -f
  for (int iter = 0; iter < 200; ++iter) {
    const double m = 0.5 * (a + b), tol = 1.5e-8 * std::abs(x) + 1e-12, tol2 = 2 * tol;
    if (std::abs(x - m) <= tol2 - 0.5 * (b - a)) break;
    double p = 0.0, q = 0.0, r = 0.0;
    if (std::abs(e) > tol) {  // parabola through x, w, v
      r = (x - w) * (fx - fv);
      q = (x - v) * (fx - fw);
      p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p;
      q = std::abs(q);
      r = e;
      e = d;
    }
    if (std::abs(p) < std::abs(0.5 * q * r) && p > q * (a - x) && p < q * (b - x)) {
      d = p / q;
      if (x + d - a < tol2 || b - x - d < tol2) d = x < m ? tol : -tol;
    } else {
      e = (x < m ? b : a) - x;
      d = c * e;
    }
    const double u = x + (std::abs(d) >= tol ? d : (d > 0 ? tol : -tol));
    const double fu = -f(u);
    if (fu <= fx) {
      (u < x ? b : a) = x;
      v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w, fv = fw, w = u, fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u, fv = fu;
      }
    }
  }
  Extremum best{-fx, x};
  for (double end : {a0, b0})
    if (const double fe = f(end); fe > best.value) best = {fe, end};
  return best;
}

// The point of [a, b] where f changes sign (f(a) and f(b) of opposite signs), by bisection.
template <class F>
double bisect_sign_change(F&& f, double a, double b) {
  const bool a_positive = f(a) > 0;
  for (int i = 0; i < 200 && std::abs(b - a) > 1e-13 * (1.0 + std::abs(a)); ++i) {
    const double m = 0.5 * (a + b);
    ((f(m) > 0) == a_positive ? a : b) = m;
  }
  return 0.5 * (a + b);
}

}  // namespace polarform
