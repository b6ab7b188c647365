// The four boundary curves of a rectangular patch (Piegl & Tiller 2001, §2): S(u, 0) = u0(u),
// S(u, 1) = u1(u), S(0, v) = v0(v), S(1, v) = v1(v), each non-rational on [0, 1], the corners
// shared. boundary_from_loop orders and orients four curves given in loop order (spec P1).
#pragma once

#include <array>

#include "src/nurbs/curve_reversal.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct PatchBoundary {
  NurbsCurve3d u0, u1;  // v = 0 and v = 1, parametrised by u
  NurbsCurve3d v0, v1;  // u = 0 and u = 1, parametrised by v
};

// Curves c0..c3 in loop order: each starts where the previous ends (the last ends where c0
// starts), within corner_tolerance (mm). A curve that runs the wrong way (its end, not its start,
// meets the previous curve) is reversed. Domains are normalised to [0, 1]. The result: u0 = c0,
// v1 = c1, u1 = c2 reversed, v0 = c3 reversed; each shared corner is snapped to the mean of the two
// curve ends meeting there. Throws InputError naming the corner (0..3, where c_k starts) and its gap
// when the ends do not meet, or for a rational curve.
PatchBoundary boundary_from_loop(const std::array<NurbsCurve3d, 4>& loop, double corner_tolerance);

}  // namespace polarform
