// Root isolation for a polynomial on [0, 1] in Bernstein form: the number of sign changes of the
// Bernstein coefficients bounds the number of roots (variation diminishing), and de Casteljau
// halving refines an interval until it has at most one sign change; Lane & Riesenfeld 1981.
// Point inversion uses it to find every stationary point of the distance to a curve.
#pragma once

#include <utility>
#include <vector>

namespace polarform {

// The Bernstein coefficients on [0, 1] of the polynomial sum_k power[k] t^k (same degree).
std::vector<double> power_to_bernstein(const std::vector<double>& power);

// Disjoint intervals [t0, t1] of [0, 1], in increasing order, that hold every root of the
// polynomial with the given Bernstein coefficients: each has exactly one sign change of its
// coefficients (then exactly one simple root) or is narrower than `width` (a root cluster). A
// polynomial with all coefficients zero has no isolated roots: the result is empty.
std::vector<std::pair<double, double>> isolate_roots(const std::vector<double>& bernstein,
                                                     double width = 1e-12);

}  // namespace polarform
