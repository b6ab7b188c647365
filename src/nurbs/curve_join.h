// Joining clamped curves end to start into one: each raised to the highest degree p among them
// (NURBS Book A5.9, degree_elevation.h), the knot vectors concatenated with multiplicity p at every
// joint (NURBS Book §5.3: a C0 junction), the shared end point once.
#pragma once

#include <vector>

#include "src/nurbs/nurbs_curve.h"

namespace polarform {

// pieces: clamped curves, each starting where the one before ends (same parameter and, to
// round-off, same point; the joint takes the earlier piece's end point). Returns their union over
// [pieces.front().front(), pieces.back().back()]. Throws InputError for no pieces, a parameter gap
// or overlap, or a joint whose points differ by more than 1e-9 of the curves' size.
NurbsCurve2d join_curves(const std::vector<NurbsCurve2d>& pieces);

}  // namespace polarform
