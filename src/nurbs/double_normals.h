// The shortest double normal of a spine curve — a chord C(t1)C(t2) perpendicular to the curve at
// both ends — whose half length is the body–body bound r_bb of a pipe (Maekawa, Patrikalakis,
// Sakkalis & Yu 1998; MIT 13.472J §8.4, the theorem after (8.46)).
#pragma once

#include "src/nurbs/spine_table.h"

namespace polarform {

struct DoubleNormal {
  double length = 0.0;  // infinity when the spine has none
  double t1 = 0.0, t2 = 0.0;
};

// The shortest chord with (C(t1) − C(t2))·C′(t1) = 0 = (C(t1) − C(t2))·C′(t2) whose feet are at
// least `separation` apart in arc length (the shorter way round for a closed spine, whose
// parameters wrap across the seam). The diagonal t1 = t2 solves the equations trivially; a spine
// with curvature ≤ κ has no other solution with feet closer than π/κ (see the .cpp), so the
// caller passes π/(2κ_max), and infinity for a straight spine.
DoubleNormal shortest_double_normal(const SpineTable& table, bool closed, double separation);

}  // namespace polarform
