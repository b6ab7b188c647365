// A curve traversed backwards on the same domain: C(a + b − u), knots u → a + b − u mirrored and
// the control points (and weights) in reverse order.
#pragma once

#include "src/nurbs/bspline.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

BSpline reversed(const BSpline& spline);
NurbsCurve2d reversed(const NurbsCurve2d& curve);
NurbsCurve3d reversed(const NurbsCurve3d& curve);

}  // namespace polarform
