// The largest curvature of a pipe spine by sampling and refinement — a stand-in used by
// pipe_bounds (pipe_self_intersection.cpp) while the exact max_curvature of pipe_surface.h (root
// isolation on Bézier pieces, spec M7) is written in parallel; at merge pipe_bounds switches to
// max_curvature and this file goes.
#pragma once

#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/pipe_surface.h"

namespace polarform {

// κ(t) = |C′ × C″| / |C′|³; MIT 13.472J eq. (8.46).
double spine_curvature(const NurbsCurve3d& spine, double t);

// max κ: every knot span sampled at 16(p + 1) points (its right end approached from inside, so a
// curvature jump at a knot counts on both sides), each sampled local maximum refined by Brent's
// method (brent_minimum.h) between its neighbours, or its one neighbour at a span end.
SpineCurvature scan_max_curvature(const NurbsCurve3d& spine);

}  // namespace polarform
