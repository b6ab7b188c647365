// Knot insertion: the same B-spline on a knot vector with one value added `times` times (NURBS Book
// A5.1). Written once for BSpline, so a NURBS curve inserts through its homogeneous BSpline and a
// surface through BSplineSurface::along_u / along_v (one direction at a time).
#pragma once

#include "src/nurbs/bspline.h"
#include "src/nurbs/bspline_surface.h"

namespace polarform {

// Inserts u `times` times (times >= 0). Throws InputError if u lies outside [front, back] or its
// multiplicity would exceed the degree.
BSpline insert_knot(const BSpline& c, double u, int times);

// The same along one direction of a surface.
BSplineSurface insert_knot_u(const BSplineSurface& s, double u, int times);
BSplineSurface insert_knot_v(const BSplineSurface& s, double v, int times);

}  // namespace polarform
