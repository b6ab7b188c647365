// The binomial coefficient C(n, k) as a double, by the product formula (exact for the small n of
// Bernstein and Leibniz sums).
#pragma once

namespace polarform {

inline double binomial(int n, int k) {
  double c = 1.0;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return c;
}

}  // namespace polarform
