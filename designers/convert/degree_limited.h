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

// Least squares on uniform knots in ψ (periodic when R is closed), the number of spans grown until
// the measured radial error meets tol. Throws NumericalError if 20000 spans do not reach it.
LimitedCurve approximate_polar_curve(const PolarFunction& R, int degree, double tol);

// Interpolation of N points R(ψ_k)(cos ψ_k, sin ψ_k) equally spaced in ψ, with the fewest N (found
// by bisection) whose measured radial error meets tol: the usual "spline through points" export.
LimitedCurve interpolate_polar_curve(const PolarFunction& R, int degree, double tol);

}  // namespace polarform
