// Polynomial: a polynomial on an interval [u0, u1] stored in the power basis of the local
// variable t = (u - u0)/(u1 - u0), evaluated with derivatives in u by Horner's rule, and converted
// exactly to its Bezier (Bernstein) form of any degree >= its own. Cam dwells, polynomial laws and
// Hermite segments use it; the Bezier form joins them into the program's exact B-spline.
#pragma once

#include <vector>

#include "src/nurbs/bspline.h"

namespace polarform {

class Polynomial {
 public:
  Polynomial() = default;
  // coefficients[i] multiplies t^i. Throws InputError unless u0 < u1 and coefficients are finite
  // and non-empty.
  Polynomial(double u0, double u1, std::vector<double> coefficients);

  double u0() const { return u0_; }
  double u1() const { return u1_; }
  int degree() const { return static_cast<int>(coefficients_.size()) - 1; }
  const std::vector<double>& coefficients() const { return coefficients_; }

  // f(u), f'(u), ..., f^(d)(u) into out[0..d] (derivatives with respect to u), any d >= 0.
  void derivatives(double u, int d, double* out) const;
  double operator()(double u) const;

  // The same polynomial scaled by a and shifted by b: a f + b.
  Polynomial affine(double a, double b) const;

  // Exact Bezier form of degree `degree` >= degree() on [u0, u1] (degree elevation by
  // b_j = sum_i C(j,i)/C(n,i) a_i; Farin, Curves and Surfaces for CAGD, degree elevation).
  BSplineFunction bezier(int degree) const;
  // Power-basis coefficients in t of the Bezier form with Bernstein coefficients b on [u0, u1].
  static Polynomial from_bezier(double u0, double u1, const std::vector<double>& b);

 private:
  double u0_ = 0.0;
  double u1_ = 1.0;
  std::vector<double> coefficients_{0.0};
};

}  // namespace polarform
