// The pieces of the prismatic STEP solids (a cam plate extruded along z): the checks a closed
// planar profile must pass, and the vertical walls — a closed profile or a circle about the z axis
// swept from z0 to z1 — with their bottom and top edges, for the solid writers to bound the planar
// faces with (ISO 10303-42 topology, export/step_topology.h).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "export/step_file.h"
#include "export/step_topology.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

// The profile, counter-clockwise. Throws InputError "<what>: …" unless it is exchangeable (degree
// >= 1, interior knots at most C0), closed within `tolerance` and encloses a non-zero area.
NurbsCurve2d counter_clockwise_profile(const NurbsCurve2d& profile, double tolerance,
                                       const std::string& what);

// Winding number of the profile around the origin and the distance from the origin to it.
std::pair<int, double> winding_and_clearance(const NurbsCurve2d& profile);

// A wall face and its edges at z0 (low) and z1 (high), both running along the curve's
// (counter-clockwise) direction. outward: the face's normal points away from the region the
// curve encloses (material inside, as the side of a cam), else towards it (a bore, a groove's
// outer flank).
struct StepWall {
  int face = 0, low = 0, high = 0;
};

// S(u, v) = C(u) + v z as the exactly equivalent B-spline surface of degree (p, 1) (Open CASCADE
// integrates mass properties over a SURFACE_OF_LINEAR_EXTRUSION with errors of a few percent),
// joined by a seam line at the profile's start.
StepWall step_profile_wall(StepFile& f, StepTopology& topo, const NurbsCurve2d& ccw_profile,
                           double z0, double z1, bool outward, double tolerance);

// A CYLINDRICAL_SURFACE wall of the given radius about the z axis, seam at (radius, 0).
StepWall step_circle_wall(StepFile& f, StepTopology& topo, double radius, double z0, double z1,
                          bool outward);

// The whole file: the faces as a CLOSED_SHELL of a MANIFOLD_SOLID_BREP in an
// ADVANCED_BREP_SHAPE_REPRESENTATION of an AP214 part named `name`.
std::string step_solid_file(StepFile& f, int context, const std::vector<std::string>& faces,
                            const std::string& name, const StepHeader& header);

}  // namespace polarform
