// Pipe surfaces (Patrikalakis & Maekawa, MIT 13.472J §8.3.2-b, eqs. (8.41)–(8.46)): P(t, θ) = C(t) +
// r (cos θ X(t) + sin θ Y(t)) around a spine C with a moving frame (sweep_frames.h); locally
// regular iff r < 1/κ_max, κ_max the largest curvature of the spine (8.46), found exactly on
// integral Bézier pieces by root isolation of (κ²)' and by bracketing and refinement on rational
// ones. The NURBS is exact for line spines (a cylinder, degree (2, 1) with the circle along u) and
// circle-arc spines (a torus piece, (2, 2)); otherwise circles in the normal planes at stations
// are skinned along the spine and stations are added until the measured max deviation from the
// analytic pipe is within the tolerance.
#pragma once

#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"
#include "src/nurbs/sweep_frames.h"

namespace polarform {

struct SpineCurvature {
  double kappa_max = 0.0;  // 1/mm
  double t_at = 0.0;       // where
};
// κ_max = infinity at a corner of the spine (a knot where the unit tangent jumps by more than
// 1e-9 rad): no pipe around it is locally regular. A straight spine gives 0.
SpineCurvature max_curvature(const NurbsCurve3d& spine);

struct PipeSurface {
  NurbsSurface surface;     // u: around (the circle), v: along the spine
  bool exact = false;       // the analytic pipe itself (line or circle-arc spine)
  double max_error = 0.0;   // measured max deviation from the analytic pipe (0 when exact)
  int sections = 0;         // stations skinned (approximate pipes)
};

// The exact pipes start from the frame at the spine's start (the fixed frame for a line when
// Frenet is asked, which is undefined there); their v runs over the spine's domain, but along a
// line linearly and along an arc by the rational quadratic arc's parameter, not the spine's. The
// skinned pipe starts with max(5, 2·spans + 1) stations equally spaced in t and doubles them
// (up to 4097); max_error is the larger of | |S − C(t*)| − r | (t* the spine point closest to a
// surface sample) and the distance from analytic pipe points to the surface, at 8 × 32 samples
// per station interval. Throws InputError for r <= 0 or a tolerance <= 0 when the pipe is not
// exact, NumericalError when 4097 stations do not meet the tolerance.
PipeSurface pipe_surface(const NurbsCurve3d& spine, double radius, FrameRule rule,
                         double tolerance);

}  // namespace polarform
