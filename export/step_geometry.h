// STEP geometry instances (ISO 10303-42 geometry_schema) for kernel types: points, directions,
// placements, lines, circles, planes, cylinders, and NURBS as b_spline_curve_with_knots /
// b_spline_surface_with_knots, rational ones as the complex instances AP214 requires. Each
// function appends to a StepFile and returns the instance id.
#pragma once

#include <Eigen/Core>
#include <string>

#include "export/step_file.h"
#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

int step_point(StepFile& f, const Eigen::Vector3d& p);
int step_direction(StepFile& f, const Eigen::Vector3d& d);  // d need not be unit
// AXIS2_PLACEMENT_3D at origin with axis z and reference direction x.
int step_axis2(StepFile& f, const Eigen::Vector3d& origin, const Eigen::Vector3d& z,
               const Eigen::Vector3d& x);
// LINE through p along the unit direction d (parameter = distance).
int step_line(StepFile& f, const Eigen::Vector3d& p, const Eigen::Vector3d& d);
int step_circle(StepFile& f, int axis2, double radius);
int step_plane(StepFile& f, int axis2);
int step_cylindrical_surface(StepFile& f, int axis2, double radius);

// The curve with its own control points. closed_curve is .T. when C(front) = C(back) within
// tolerance, except for the one case explained at its definition.
int step_bspline_curve(StepFile& f, const NurbsCurve3d& c, double tolerance,
                       const std::string& name = "");
int step_bspline_surface(StepFile& f, const NurbsSurface& s, double tolerance,
                         const std::string& name = "");

}  // namespace polarform
