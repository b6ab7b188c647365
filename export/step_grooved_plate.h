// A grooved plate cam as a STEP solid: a disc of the given thickness (z = 0 to thickness) whose
// radius is the outer flank's largest radius plus a rim width, with a face groove cut from its top
// face to `depth`, between the inner and the outer flank (closed planar NURBS profiles about the z
// axis, the inner inside the outer), and optionally a bore. One MANIFOLD_SOLID_BREP: bottom and
// rim, the top face in two pieces (the ring outside the groove, the island inside it), the two
// flank walls as exact B-spline extrusions, the groove's planar floor and the bore, in an AP214
// part (export/step_prism.h).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "export/step_file.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct GroovedPlate {
  NurbsCurve2d inner, outer;            // the groove's flanks
  double rim = 0.0;                     // mm, of material outside the outer flank's largest radius
  double thickness = 0.0;               // mm
  double depth = 0.0;                   // mm, of the groove, < thickness
  std::optional<double> bore_diameter;  // mm
};

// The whole STEP file. Throws InputError unless both flanks are closed profiles (step_prism.h)
// winding once around the origin, the inner flank lies inside the outer one, the rim > 0, 0 < depth
// < thickness (all finite), and the bore inside the inner flank.
std::string step_grooved_plate_solid(const GroovedPlate& plate, const std::string& name = "cam",
                                     const StepHeader& header = {});

}  // namespace polarform
