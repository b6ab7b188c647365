// Single unit-circle arcs as NURBS curves on η ∈ [0, 1], centre at the origin: the rational
// quadratic Bezier (RQB) arc and the Blanc–Schlick quasi-uniform quartic arc. The quartic arc is
// built in homogeneous form (w·b1 of the RQB arc), so it also exists for a 180° sweep where the
// RQB's middle control point is at infinity.
#pragma once

#include <Eigen/Core>

#include "src/base/arc_angle.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

// Homogeneous control points (w·x, w·y, w) of one arc from angle `start` to `end`, as the
// 3 x (degree + 1) columns of a rational Bezier curve (degree 2 for rqb, 4 for quartic; `alpha` is
// used by quartic arcs only). Requires 0 < end − start < π (rqb) or ≤ π (quartic).
Eigen::MatrixXd arc_homogeneous_points(ArcKind kind, double start, double end, double alpha);

// RQB arc of the unit circle from angle `start` through `sweep` (0 < sweep < π); Bae 2002, (2.4).
NurbsCurve2d rqb_arc(double start, double sweep);

// Quasi-uniform quartic arc from `start` through `sweep` (0 < sweep <= π) with the given α > 0;
// Bae 2002, eq. (5.2).
NurbsCurve2d quartic_arc(double start, double sweep, double alpha);

}  // namespace polarform
