// Periodic (closed) B-splines and clipping (Bae 2002, §3.3.1): the unclamped knot vector extended
// periodically past both ends (3.9), the closed B-spline whose first `degree` control values repeat
// at the end (3.10), and clip, which cuts the clamped piece over [a, b] out of any B-spline by
// multiple knot insertion (how a closed fit becomes an open, clamped F over [v_s, v_e]).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/bspline.h"
#include "src/nurbs/bspline_surface.h"

namespace polarform {

// breaks: b_0 = v_s < ... < b_k = v_e (k >= 1). Returns b_0..b_k preceded by `degree` knots and
// followed by `degree` knots that repeat the spacings periodically (period b_k - b_0), eq. (3.9).
Knots periodic_knots(int degree, const std::vector<double>& breaks);

// The same with multiple knots: one period's knots T_0 = v_s <= T_1 <= ... <= T_{K-1} < v_e = end
// (K >= 1; a value repeated m <= degree times is a knot of multiplicity m, T_0 repeated the seam's,
// C^{degree-m} across v_s / v_e), continued by the period: U_i = T_{i mod K} + (v_e − v_s)·⌊i/K⌋
// for i = −degree..K + degree, eq. (3.9). K distinct control values.
Knots periodic_knots(int degree, const std::vector<double>& period_knots, double end);

// The closed B-spline on periodic_knots(degree, breaks) with the k columns of coefs as its distinct
// control values and the first `degree` of them repeated at the end, eq. (3.10): C^{degree-1}
// across v_s / v_e.
BSpline periodic_bspline(int degree, const std::vector<double>& breaks,
                         const Eigen::MatrixXd& coefs);

// The piece of c over [a, b] (front <= a < b <= back) as a clamped B-spline: a and b are inserted
// up to multiplicity p (NURBS Book A5.1) and the coefficients outside are dropped. Works on clamped
// and unclamped knot vectors; at a knot of multiplicity p+1 the piece takes the side inside [a, b].
BSpline clip(const BSpline& c, double a, double b);
BSplineSurface clip_u(const BSplineSurface& s, double a, double b);
BSplineSurface clip_v(const BSplineSurface& s, double a, double b);

}  // namespace polarform
