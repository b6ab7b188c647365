// Geometric facts the exchange writers state about kernel curves and surfaces: whether a spline can
// be exchanged at all (degree >= 1, interior knots at most C0), closure and periodic knot structure,
// planarity with the plane normal, exact iso-parametric boundary curves of a surface, and extents.
// Every flag a writer sets truthfully (IGES 126/128 PROP flags, STEP closed_curve, DXF 70) comes
// from here.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string_view>
#include <vector>

#include "src/nurbs/curve_reversal.h"
#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

// Throws InputError naming `what` unless degree >= 1 and every knot value strictly between the
// first and the last has multiplicity <= degree (a multiplicity of degree + 1 lets the curve jump;
// Open CASCADE and most CAD importers drop control points to "repair" it, see DESIGN.md §4.6).
void require_exchangeable(int degree, const Knots& knots, std::string_view what);

// The 2D curve as a 3D curve in the plane z = 0, with identical knots and weights.
NurbsCurve3d lift_to_3d(const NurbsCurve2d& curve);

// The curve moved by offset.
NurbsCurve3d translated(const NurbsCurve3d& curve, const Eigen::Vector3d& offset);

// The exact iso-parametric curves S(u, .) (knots of v) and S(., v) (knots of u): the homogeneous
// control net contracted with the basis functions of the fixed direction.
NurbsCurve3d iso_curve_at_u(const NurbsSurface& surface, double u);
NurbsCurve3d iso_curve_at_v(const NurbsSurface& surface, double v);

// C(front) and C(back) closer than tolerance.
bool is_closed(const NurbsCurve3d& curve, double tolerance);
// The boundary curves u = front/back (resp. v = front/back) coincide within tolerance, compared at
// 8 parameters per knot span of the other direction.
bool is_closed_u(const NurbsSurface& surface, double tolerance);
bool is_closed_v(const NurbsSurface& surface, double tolerance);
// All control points within tolerance of the first: the curve is a single point (a surface pole).
bool is_degenerate(const NurbsCurve3d& curve, double tolerance);

// Periodic (wrapped) structure of a degree-p spline with n coefficients: knot spacing repeats
// with period u_n - u_p (U[i + n - p] - U[i] = u_n - u_p for i = 0..2p) and the last p homogeneous
// coefficients repeat the first p. Such a spline is closed with C^(p-1) continuity at the seam.
bool has_periodic_structure(const BSpline& homogeneous);

// Unit normal of a plane holding all points within tolerance, or nullopt. Axis-aligned planes give
// the exact axis; collinear or coincident points give some normal of a plane through them. The
// sign makes the largest-magnitude component positive.
std::optional<Eigen::Vector3d> plane_normal(const std::vector<Eigen::Vector3d>& points,
                                            double tolerance);

std::vector<Eigen::Vector3d> control_points_of(const NurbsCurve3d& curve);
std::vector<Eigen::Vector3d> control_points_of(const NurbsSurface& surface);

// Largest absolute coordinate of the points (0 for none).
double max_abs_coordinate(const std::vector<Eigen::Vector3d>& points);

}  // namespace polarform
