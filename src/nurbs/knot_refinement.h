// Knot refinement: the same B-spline on a knot vector with many values inserted in one pass
// (NURBS Book A5.4). Written once for BSpline; surfaces refine one direction at a time through
// BSplineSurface::along_u / along_v.
#pragma once

#include <vector>

#include "src/nurbs/bspline.h"
#include "src/nurbs/bspline_surface.h"

namespace polarform {

// Inserts the values X (non-decreasing, inside [front, back], a value listed as often as it is to
// be inserted). Throws InputError if X is unsorted, leaves the domain, or a multiplicity would
// exceed the degree.
BSpline refine_knots(const BSpline& c, const std::vector<double>& X);

// The same along one direction of a surface.
BSplineSurface refine_knots_u(const BSplineSurface& s, const std::vector<double>& X);
BSplineSurface refine_knots_v(const BSplineSurface& s, const std::vector<double>& X);

}  // namespace polarform
