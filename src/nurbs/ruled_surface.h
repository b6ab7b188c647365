// Ruled surface (linear loft) between two curves and the bilinear patch of four corners (NURBS Book
// §8.2, §8.4; spec B5): S(u, v) = (1 − v)·C0(u) + v·C1(u), u the curves' common parameter, v in
// [0, 1] of degree 1.
#pragma once

#include <Eigen/Core>

#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

// Both curves on one basis (common_basis: degree elevation, union knots); the rows v = 0 and v = 1
// of the net are their control points. Exact for rational curves whose weight functions agree up
// to a constant factor (then the homogeneous blend is the Cartesian one); any other rational pair
// throws InputError, as does a mismatch of the parameter domains.
NurbsSurface ruled_surface(const NurbsCurve3d& c0, const NurbsCurve3d& c1);

// The bilinear patch S(u, v) = (1−u)(1−v)p00 + u(1−v)p10 + (1−u)v p01 + uv p11 on [0, 1]²,
// degree (1, 1).
NurbsSurface bilinear_surface(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10,
                              const Eigen::Vector3d& p01, const Eigen::Vector3d& p11);

}  // namespace polarform
