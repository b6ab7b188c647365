// The normalised polynomial law of a stated degree from constraints: S(x) on [0, 1] of degree n
// whose value or derivative meets each constraint S^(k)(x_i) = value_i (end and interior alike).
// n + 1 independent constraints determine it; with fewer, it is the one of least jerk energy
// ∫₀¹ S‴(x)² dx (a quadratic programme with linear equality constraints, solved through its KKT
// system; Norton, Cam Design and Manufacturing Handbook, polynomial functions, for the exactly
// determined case; Chen, Mechanics and Design of Cam Mechanisms, polynomial cams). Solved for the
// Bernstein coefficients, whose system is better conditioned than the power basis's.
#pragma once

#include <span>
#include <string>

#include "designers/cam/polynomial.h"

namespace polarform {

// The highest degree of a constrained polynomial law (the profile's degree is about 4 higher).
inline constexpr int kMaxConstrainedPolynomialDegree = 20;
// The highest derivative an interior constraint may fix (s, v, a, j, snap).
inline constexpr int kMaxConstraintDerivative = 4;

// S^(derivative)(x) = value, in normalised units: x = (θ − start)/β, S = (s − start level)/±lift,
// so S^(k) = s^(k)·β^k/(±lift).
struct PolynomialConstraint {
  double x = 0.5;
  int derivative = 0;
  double value = 0.5;

  bool operator==(const PolynomialConstraint&) const = default;
};

struct ConstrainedPolynomial {
  Polynomial polynomial;           // on [0, 1]
  bool least_jerk_energy = false;  // fewer constraints than coefficients: the least-jerk one
};

// Throws InputError stating the counts when there are more constraints than the n + 1
// coefficients, when the constraints are not independent (contradictory or repeated), or when
// they are too few for the jerk energy to fix the polynomial (it then leaves a quadratic free);
// and for a degree outside [1, kMaxConstrainedPolynomialDegree], an x outside [0, 1], a
// derivative outside [0, degree] or a non-finite value.
ConstrainedPolynomial constrained_polynomial(int degree,
                                             std::span<const PolynomialConstraint> constraints);

// The largest |p^(k)(t)| over t in [0, 1] of a polynomial in its local variable t, k = 1, 2, 3: at
// the ends or at a real root of p^(k+1) in (0, 1) (the companion matrix's eigenvalues, polished by
// Newton steps). Of a normalised law these are the peak factors Cv, Ca, Cj.
struct PolynomialPeaks {
  double cv = 0.0, ca = 0.0, cj = 0.0;
};
PolynomialPeaks polynomial_peaks(const Polynomial& p);

}  // namespace polarform
