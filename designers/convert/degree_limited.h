// Degree-limited profiles for consumers that cap the spline degree (AutoCAD's DXF reader at 10,
// many CAM systems at 3): a non-rational B-spline of the requested degree that approximates the
// polar curve r = R(ψ) within the tolerance, with the error measured on the result. Also the
// baseline a CAD user would otherwise build: a spline interpolating points sampled from the exact
// profile, as many as needed.
#pragma once

#include "designers/convert/polar_function.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct LimitedCurve {
  NurbsCurve2d curve;           // clamped; closed (C^{p-1} at the seam) when R is closed
  double max_radial_error = 0;  // mm, measured against R
  double max_normal_error = 0;  // mm
  int control_points = 0;
};

// A tolerance-driven least-squares B-spline with knots placed by need (periodic, C^{p-1} across
// the seam, when R is closed; an open one keeps R's end points): knots equidistributing the
// measured error (de Boor), a knot wherever a derivative of order <= min(p, 3) of R jumps, the
// fewest spans on that density whose minimax fit meets tol, knot removal by refit, then the
// result measured against R itself (a span split where it misses). The fits let the curve slide
// along the profile and are pushed toward the minimax radial error (profile_fit.h). Throws
// NumericalError if 20000 spans do not reach tol.
LimitedCurve approximate_polar_curve(const PolarFunction& R, int degree, double tol);

// Interpolation of N points R(ψ_k)(cos ψ_k, sin ψ_k) equally spaced in ψ, with the fewest N (found
// by bisection) whose measured radial error meets tol: the usual "spline through points" export.
LimitedCurve interpolate_polar_curve(const PolarFunction& R, int degree, double tol);

}  // namespace polarform
