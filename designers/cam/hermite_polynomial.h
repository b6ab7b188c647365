// The general polynomial cam segment: the two-point Hermite polynomial of minimal degree that meets
// prescribed displacement and derivatives at both ends of [u0, u1] (Bae 2002, eq. (5.1) with
// arbitrary values; Rothbart, Cams, 1956). Three values per end give the quintic (3-4-5 family),
// four give the degree-7 polynomial (4-5-6-7 family).
#pragma once

#include <span>

#include "designers/cam/polynomial.h"

namespace polarform {

// f^(i)(u0) = start[i] and f^(i)(u1) = end[i] for i = 0..k, k = start.size() - 1 <= 3, derivatives
// with respect to u; the result has degree 2k + 1. Throws InputError when the spans differ in size,
// are empty or longer than 4, or the interval is empty.
Polynomial hermite_polynomial(double u0, double u1, std::span<const double> start, std::span<const double> end);

}  // namespace polarform
