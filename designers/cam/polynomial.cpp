#include "designers/cam/polynomial.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/number_text.h"
#include "src/nurbs/binomial.h"

namespace polarform {

Polynomial::Polynomial(double u0, double u1, std::vector<double> coefficients)
    : u0_(u0), u1_(u1), coefficients_(std::move(coefficients)) {
  if (!(u0_ < u1_) || !std::isfinite(u0_) || !std::isfinite(u1_))
    throw InputError("polynomial: interval [" + number_text(u0_) + ", " + number_text(u1_) +
                     "] must be finite with u0 < u1");
  if (coefficients_.empty()) throw InputError("polynomial: no coefficients");
  for (double c : coefficients_)
    if (!std::isfinite(c)) throw InputError("polynomial: a coefficient is not finite");
}

void Polynomial::derivatives(double u, int d, double* out) const {
  const double h = u1_ - u0_, t = (u - u0_) / h;
  const int n = degree();
  double scale = 1.0;  // h^-k
  for (int k = 0; k <= d; ++k) {
    double value = 0.0;
    // Horner on sum_{i>=k} a_i i!/(i-k)! t^(i-k).
    for (int i = n; i >= k; --i) {
      double falling = 1.0;
      for (int j = 0; j < k; ++j) falling *= i - j;
      value = value * t + coefficients_[i] * falling;
    }
    out[k] = value * scale;
    scale /= h;
  }
}

double Polynomial::operator()(double u) const {
  double value;
  derivatives(u, 0, &value);
  return value;
}

Polynomial Polynomial::affine(double a, double b) const {
  std::vector<double> c = coefficients_;
  for (double& x : c) x *= a;
  c[0] += b;
  return Polynomial(u0_, u1_, std::move(c));
}

BSplineFunction Polynomial::bezier(int degree) const {
  const int n = this->degree();
  if (degree < n)
    throw InputError("polynomial: Bezier degree " + std::to_string(degree) + " below the polynomial degree " +
                     std::to_string(n));
  Eigen::VectorXd b(degree + 1);
  for (int j = 0; j <= degree; ++j) {
    double sum = 0.0;
    for (int i = 0; i <= std::min(j, n); ++i) sum += binomial(j, i) / binomial(degree, i) * coefficients_[i];
    b(j) = sum;
  }
  return BSplineFunction(degree, clamped_knots(degree, u0_, u1_), b);
}

// Bernstein to power basis: a_i = C(n,i) sum_k (-1)^(i-k) C(i,k) b_k; Farin, Curves and Surfaces for CAGD (monomial form of a Bezier curve).
Polynomial Polynomial::from_bezier(double u0, double u1, const std::vector<double>& b) {
  const int n = static_cast<int>(b.size()) - 1;
  std::vector<double> a(n + 1);
  for (int i = 0; i <= n; ++i) {
    double sum = 0.0;
    for (int k = 0; k <= i; ++k) sum += ((i - k) % 2 ? -1.0 : 1.0) * binomial(i, k) * b[k];
    a[i] = binomial(n, i) * sum;
  }
  return Polynomial(u0, u1, std::move(a));
}

}  // namespace polarform
