#include "src/nurbs/bernstein_roots.h"

#include <cmath>

#include "src/nurbs/binomial.h"

namespace polarform {

namespace {

// Sign changes of the sequence, zeros skipped.
int sign_changes(const std::vector<double>& b) {
  int changes = 0;
  double last = 0.0;
  for (double x : b) {
    if (x == 0.0) continue;
    if (last != 0.0 && (x > 0.0) != (last > 0.0)) ++changes;
    last = x;
  }
  return changes;
}

void isolate(const std::vector<double>& b, double t0, double t1, double width,
             std::vector<std::pair<double, double>>& out) {
  const int changes = sign_changes(b);
  if (changes == 0) return;
  if (changes == 1 || t1 - t0 < width) {
    out.emplace_back(t0, t1);
    return;
  }
  // de Casteljau at t = 1/2: the left half's coefficients are the first entries of each level,
  // the right half's the last ones.
  const std::size_t n = b.size();
  std::vector<double> level = b, left(n), right(n);
  for (std::size_t r = 0; r < n; ++r) {
    left[r] = level[0];
    right[n - 1 - r] = level[n - 1 - r];
    for (std::size_t i = 0; i + 1 < n - r; ++i) level[i] = 0.5 * (level[i] + level[i + 1]);
  }
  const double mid = 0.5 * (t0 + t1);
  isolate(left, t0, mid, width, out);
  isolate(right, mid, t1, width, out);
}

}  // namespace

// Farouki & Rajan 1987, power-to-Bernstein basis conversion: b_i = sum_{k<=i} C(i,k)/C(m,k) c_k.
std::vector<double> power_to_bernstein(const std::vector<double>& power) {
  const int m = static_cast<int>(power.size()) - 1;
  std::vector<double> b(power.size(), 0.0);
  for (int i = 0; i <= m; ++i)
    for (int k = 0; k <= i; ++k) b[i] += binomial(i, k) / binomial(m, k) * power[k];
  return b;
}

// Lane & Riesenfeld 1981 (subdivision with the variation-diminishing sign count).
std::vector<std::pair<double, double>> isolate_roots(const std::vector<double>& bernstein,
                                                     double width) {
  std::vector<std::pair<double, double>> out;
  if (!bernstein.empty()) isolate(bernstein, 0.0, 1.0, width, out);
  return out;
}

}  // namespace polarform
