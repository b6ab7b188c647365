// Translational sweep of a NURBS curve along a straight direction (an extrusion, a general
// cylinder): S(u, v) = C(u) + v·d for v in [v0, v1], degree (p, 1), exact for rational C because
// the weights do not depend on v (Kantz 2003, §3.4, eqs. (3.10)–(3.11) with a linear trajectory;
// NURBS Book §8.3). u keeps C's degree, knots and parameter; the normal S_u × S_v is C'(u) × d.
#pragma once

#include <Eigen/Core>

#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

// Kantz (3.11) with T(v) = v·d: P_ij = Q_i + v_j·d, w_ij = w_i, knots_v {v0, v0, v1, v1}.
// Throws InputError unless v0 < v1 (finite) and d is finite and non-zero.
NurbsSurface extrude(const NurbsCurve3d& curve, const Eigen::Vector3d& direction, double v0,
                     double v1);

}  // namespace polarform
