// B-spline basis functions and their derivatives at one parameter; NURBS Book A2.2 / A2.3.
#pragma once

#include <Eigen/Core>

#include "src/nurbs/knots.h"

namespace polarform {

// The p+1 non-vanishing basis functions N_{span-p..span, p}(u) into N[0..p]; NURBS Book A2.2.
void basis_funs(int span, double u, int p, const Knots& knots, double* N);

// basis_funs at `count` parameters u[0..count) of one knot span, into N[i·(p+1) + j]: A2.2 with
// the span's knot differences inverted once instead of at every parameter.
void basis_funs_on_span(int span, const double* u, int count, int p, const Knots& knots, double* N);

// Derivatives 0..d of the p+1 non-vanishing basis functions into ders[k*(p+1) + j]
// (k-th derivative of N_{span-p+j, p}); derivatives above p are zero. NURBS Book A2.3.
void ders_basis_funs(int span, double u, int p, int d, const Knots& knots, double* ders);

// Convenience form of ders_basis_funs: a (d+1) x (p+1) matrix.
Eigen::MatrixXd ders_basis_funs(int span, double u, int p, int d, const Knots& knots);

}  // namespace polarform
