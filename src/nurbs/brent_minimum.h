// One-dimensional minimisation on a bracket by Brent's method (golden section with parabolic
// steps; Brent, Algorithms for Minimization without Derivatives, 1973, ch. 5, procedure fmin),
// used to refine an extremum first bracketed on a sample grid. The ends of the bracket are
// candidates too.
#pragma once

#include <algorithm>
#include <cmath>

namespace polarform {

struct Minimum {
  double x = 0.0;
  double value = 0.0;
};

// Where a search starts when f is already known at the bracket's ends and at a point x between
// them no higher than either (a sampled minimum): the first step is the parabola through the three.
struct BrentStart {
  double x, fx, fa, fb;
};

// The minimum of f on [a, b] to a relative tolerance of sqrt(machine epsilon) in x (the best a
// smooth minimum allows) plus `absolute` (< 0: 1e-15 of the bracket); Brent 1973, ch. 5 (fmin).
// Without `start`, from the golden-section point of [a, b].
template <class F>
Minimum brent_minimum(F&& f, double a, double b, double absolute = -1.0,
                      const BrentStart* start = nullptr) {
  constexpr double c = 0.3819660112501051;  // (3 − √5)/2
  const double a0 = a, b0 = b;
  double x = a + c * (b - a), w = x, v = x, d = 0.0, e = 0.0;
  double fx, fw, fv;
  if (start) {  // the ends as the two previous points, the step before last the whole bracket
    x = start->x, fx = start->fx, w = a, fw = start->fa, v = b, fv = start->fb;
    d = e = b - a;
  } else {
    fx = fw = fv = f(x);
  }
  for (int iter = 0; iter < 200; ++iter) {
    const double m = 0.5 * (a + b),
                 tol = 1.5e-8 * std::abs(x) + (absolute >= 0 ? absolute : 1e-15 * (b0 - a0)),
                 tol2 = 2 * tol;
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
    const double fu = f(u);
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
  Minimum best{x, fx};
  for (const double end : {a0, b0})
    if (const double fe = start ? (end == a0 ? start->fa : start->fb) : f(end); fe < best.value)
      best = {end, fe};
  return best;
}

}  // namespace polarform
