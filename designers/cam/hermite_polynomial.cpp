#include "designers/cam/hermite_polynomial.h"

#include <string>
#include <vector>

#include "src/error.h"
#include "src/nurbs/binomial.h"

namespace polarform {
namespace {

double falling_factorial(int n, int i) {  // n!/(n-i)!
  double f = 1.0;
  for (int m = 0; m < i; ++m) f *= n - m;
  return f;
}

}  // namespace

// Bezier end derivatives f^(i)(0) = n!/(n-i)! Δ^i b_0 and f^(i)(1) = n!/(n-i)! ∇^i b_n
// (Farin, Curves and Surfaces for CAGD, derivatives of a Bezier curve) give the control values of each end directly.
Polynomial hermite_polynomial(double u0, double u1, std::span<const double> start, std::span<const double> end) {
  if (start.size() != end.size() || start.empty() || start.size() > 4)
    throw InputError("Hermite polynomial: expected 1 to 4 values at each end and the same number at both, got " +
                     std::to_string(start.size()) + " and " + std::to_string(end.size()));
  if (!(u0 < u1)) throw InputError("Hermite polynomial: empty interval");
  const int k = static_cast<int>(start.size()) - 1, n = 2 * k + 1;
  const double h = u1 - u0;
  std::vector<double> b(n + 1);
  for (int j = 0; j <= k; ++j) {
    double front = 0.0, back = 0.0, hi = 1.0;
    for (int i = 0; i <= j; ++i) {
      const double falling = falling_factorial(n, i);
      front += binomial(j, i) * start[i] * hi / falling;
      back += binomial(j, i) * (i % 2 ? -1.0 : 1.0) * end[i] * hi / falling;
      hi *= h;
    }
    b[j] = front;
    b[n - j] = back;
  }
  return Polynomial::from_bezier(u0, u1, b);
}

}  // namespace polarform
