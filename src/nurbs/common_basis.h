// Several B-splines on one domain rewritten on one basis and stacked as the rows of one B-spline:
// each is degree-elevated to the highest degree (NURBS Book A5.9) and refined (A5.4) to the union
// of the knots, each value with its highest multiplicity. The rows of a homogeneous curve or
// surface must share a basis; this is how differently built factors get one.
#pragma once

#include <vector>

#include "src/nurbs/bspline.h"
#include "src/nurbs/bspline_surface.h"

namespace polarform {

// Throws InputError if parts is empty or the domains differ.
BSpline common_basis(const std::vector<BSpline>& parts);
// The same per direction for surfaces.
BSplineSurface common_basis(const std::vector<BSplineSurface>& parts);

}  // namespace polarform
