// Test oracles shared by the cam tests: an 8th-order central finite difference (an independent
// check of exact derivatives, never used by the library), a dense-sampling + ternary-search
// maximiser (locates extrema without reading formulas back) and the peak factors it measures.
#pragma once

#include <cmath>
#include <functional>

namespace polarform::test {

// f'(x) by the 8th-order central difference with step h.
inline double central_difference(const std::function<double(double)>& f, double x, double h) {
  constexpr double c[4] = {4.0 / 5, -1.0 / 5, 4.0 / 105, -1.0 / 280};
  double sum = 0.0;
  for (int k = 1; k <= 4; ++k) sum += c[k - 1] * (f(x + k * h) - f(x - k * h));
  return sum / h;
}

struct Maximum {
  double value;
  double x;
};

// max of f on [a, b]: 4000 samples, then ternary search around the best one.
inline Maximum dense_maximum(const std::function<double(double)>& f, double a, double b) {
  const int n = 4000;
  int best = 0;
  double best_value = f(a);
  for (int i = 1; i <= n; ++i) {
    const double v = f(a + (b - a) * i / n);
    if (v > best_value) best_value = v, best = i;
  }
  double lo = a + (b - a) * std::max(best - 1, 0) / n, hi = a + (b - a) * std::min(best + 1, n) / n;
  for (int it = 0; it < 200; ++it) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    (f(m1) < f(m2) ? lo : hi) = f(m1) < f(m2) ? m1 : m2;
  }
  const double x = 0.5 * (lo + hi);
  return f(x) > best_value ? Maximum{f(x), x} : Maximum{best_value, a + (b - a) * best / n};
}

// The peak factors Cv, Ca, Cj of a normalised law, law(x, k) = S^(k)(x): the maxima of |S^(k)|
// on [0, 1] for k = 1, 2, 3, measured.
struct PeakFactors {
  double cv, ca, cj;
};
inline PeakFactors peak_factors(const std::function<double(double, int)>& law) {
  double peaks[3];
  for (int k = 1; k <= 3; ++k)
    peaks[k - 1] = dense_maximum([&](double x) { return std::abs(law(x, k)); }, 0, 1).value;
  return {peaks[0], peaks[1], peaks[2]};
}

}  // namespace polarform::test
