// Surfaces of revolution: a NURBS profile curve swept about an axis into an exact rational
// NurbsSurface (NURBS Book A8.1). u runs around the axis (degree 2, one rational quadratic arc per
// quarter turn or less, u in [0, 1]), v along the profile (its degree, knots and parameter). The
// surface normal S_u × S_v points away from the axis where the profile runs along +axis_direction.
#pragma once

#include <Eigen/Core>
#include <numbers>

#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

// The profile rotated by 0..angle (radians, counter-clockwise about axis_direction) about the
// line through axis_point. S(0, v) is the profile; S(1, v) the profile rotated by `angle`, exactly
// equal to S(0, v) for a full turn. Profile control points on the axis become poles (all points of
// their row coincide). Throws InputError unless axis_point and axis_direction are finite,
// axis_direction is non-zero and 0 < angle <= 2π.
NurbsSurface revolve(const NurbsCurve3d& profile, const Eigen::Vector3d& axis_point,
                     const Eigen::Vector3d& axis_direction, double angle = 2 * std::numbers::pi);

}  // namespace polarform
