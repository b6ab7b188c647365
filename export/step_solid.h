// A closed planar profile (a cam) as a STEP solid: the profile extruded along +z from z = 0 to
// z = thickness (then rigidly placed, when a placement is given), optionally with a bore of the
// given diameter around the z axis, written as a MANIFOLD_SOLID_BREP (planar top and bottom faces
// bounded by the exact NURBS profile and the bore circle, the side face as the exact B-spline
// extrusion of the profile, a CYLINDRICAL_SURFACE bore face) in an
// ADVANCED_BREP_SHAPE_REPRESENTATION of an AP214 part: CAD systems import a solid.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "export/step_file.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

// The whole STEP file. Throws InputError unless: the profile is exchangeable (degree >= 1, interior
// knots at most C0) and closed within header.resolution with a non-zero enclosed area (either
// orientation; a clockwise profile is reversed), thickness is finite and > 0, and the bore (if
// any) has a finite diameter > 0, lies around the origin inside the profile and clear of it.
// `placement` maps the profile's frame (x, y, z = extrusion) into the file's coordinates.
std::string step_extruded_solid(const NurbsCurve2d& closed_profile, double thickness,
                                std::optional<double> bore_diameter,
                                const std::string& name = "cam", const StepHeader& header = {},
                                const std::optional<Eigen::Isometry3d>& placement = {});

// The same, written atomically to path (FILE_NAME defaults to the path's file name).
void write_step_extruded_solid(const std::filesystem::path& path, const NurbsCurve2d& closed_profile,
                               double thickness, std::optional<double> bore_diameter,
                               const std::string& name = "cam", const StepHeader& header = {});

}  // namespace polarform
