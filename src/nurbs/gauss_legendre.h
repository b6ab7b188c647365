// Composite Gauss–Legendre quadrature (Abramowitz & Stegun 25.4.30): 4 nodes on each of
// `intervals` equal parts of [a, b], exact for polynomials of degree 7 on each part.
#pragma once

#include <array>

namespace polarform {

inline constexpr std::array<double, 4> kGaussLegendre4Nodes = {
    -0.8611363115940526, -0.3399810435848563, 0.3399810435848563, 0.8611363115940526};
inline constexpr std::array<double, 4> kGaussLegendre4Weights = {
    0.3478548451374538, 0.6521451548625461, 0.6521451548625461, 0.3478548451374538};

// ∫_a^b f(t) dt.
template <class F>
double integrate_gauss_legendre(F&& f, double a, double b, int intervals) {
  double sum = 0.0;
  const double h = (b - a) / intervals;
  for (int k = 0; k < intervals; ++k)
    for (int i = 0; i < 4; ++i)
      sum += 0.5 * h * kGaussLegendre4Weights[i] *
             f(a + h * (k + 0.5 * (1 + kGaussLegendre4Nodes[i])));
  return sum;
}

// Calls visit(t, w) at every node t with its weight w, so that Σ w f(t) ≈ ∫_a^b f.
template <class V>
void visit_gauss_legendre(V&& visit, double a, double b, int intervals) {
  const double h = (b - a) / intervals;
  for (int k = 0; k < intervals; ++k)
    for (int i = 0; i < 4; ++i)
      visit(a + h * (k + 0.5 * (1 + kGaussLegendre4Nodes[i])), 0.5 * h * kGaussLegendre4Weights[i]);
}

}  // namespace polarform
