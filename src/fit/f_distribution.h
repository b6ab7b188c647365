// The F distribution's upper tail P(F > f) with (d1, d2) degrees of freedom and its critical
// value, for the F-test of nested least-squares models (Draper & Smith, Applied Regression
// Analysis, §6.2): the regularized incomplete beta function I_x(a, b) evaluated by its continued
// fraction (Numerical Recipes 3rd ed., §6.4), valid for the very large d2 of dense scans.
#pragma once

namespace polarform {

// I_x(a, b) for a, b > 0 and 0 <= x <= 1 (Numerical Recipes §6.4, eq. (6.4.5) with Lentz's method).
double incomplete_beta(double a, double b, double x);

// P(F > f) = I_{d2/(d2 + d1 f)}(d2/2, d1/2) (Abramowitz & Stegun 26.6.2); 1 for f <= 0.
double f_upper_tail(double f, double d1, double d2);

// The f with P(F > f) = alpha (0 < alpha < 1), by bisection on f_upper_tail.
double f_critical_value(double alpha, double d1, double d2);

}  // namespace polarform
