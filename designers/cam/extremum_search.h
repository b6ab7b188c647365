// One-dimensional searches used by the cam analyses on top of a sampled grid: refinement of a
// sampled extremum (Brent's method) and bisection of a sign change. They assume the function is
// unimodal / changes sign once inside the bracket.
#pragma once

#include <cmath>

#include "src/nurbs/brent_minimum.h"

namespace polarform {

struct Extremum {
  double value = 0.0;
  double theta = 0.0;  // rad
};

// Maximum of f on [a, b] by Brent's method (brent_minimum of −f) to a relative angle tolerance of
// sqrt(machine epsilon) plus 1e-12 rad; the ends are candidates too.
template <class F>
Extremum refine_maximum(F&& f, double a, double b) {
  const Minimum m = brent_minimum([&](double x) { return -f(x); }, a, b, 1e-12);
  return {-m.value, m.x};
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
