// Degree elevation: the same B-spline written with degree p + t; every interior knot gains
// multiplicity t, the ends become p + t + 1. Done as in NURBS Book §5.5 (the three steps that A5.9
// fuses): Bezier decomposition, elevation of each piece (eq. (5.36)), removal of the added knots,
// here by the stable removal of KnotRemover (A5.9's one-sided removal loses up to all digits next
// to nearly coincident knots). Written once for BSpline; surfaces elevate one direction at a time.
#pragma once

#include "src/nurbs/bspline.h"
#include "src/nurbs/bspline_surface.h"

namespace polarform {

// Elevates by t >= 0; the result is clamped to c's domain (an unclamped knot vector is clipped).
// Throws InputError if t < 0, the result would exceed kMaxDegree, or an interior knot has
// multiplicity p+1 (a discontinuity).
BSpline elevate_degree(const BSpline& c, int t);

BSplineSurface elevate_degree_u(const BSplineSurface& s, int t);
BSplineSurface elevate_degree_v(const BSplineSurface& s, int t);

}  // namespace polarform
