// Open CASCADE as the peer converter (issue 14): GeomAPI_PointsToBSpline fitted to dense samples of
// the contour r = R(θ), the curve verified by polarform's own dense measurement
// (conversion_error.h) like polarform's curves. Compiled only where Open CASCADE is found
// (POLARFORM_HAVE_OCCT); kOcctPeersAvailable says so, so that callers test it with `if constexpr`
// rather than `#if`.
#pragma once

#include "designers/convert/peer_fit.h"
#include "designers/convert/polar_function.h"

namespace polarform {

#ifdef POLARFORM_HAVE_OCCT
inline constexpr bool kOcctPeersAvailable = true;
#else
inline constexpr bool kOcctPeersAvailable = false;
#endif

// PeerCurve occt_points_to_bspline(R, deg_min, deg_max, tol)
//
// Open CASCADE's GeomAPI_PointsToBSpline(samples, deg_min, deg_max, GeomAbs_C2, Tol3D) on the
// 1441 samples of peer_contour_samples, for Tol3D = tol·{2, 1.4, 1, 0.7, 0.5, 0.35, 0.25} in turn
// (OCCT checks Tol3D at the samples only, and a looser Tol3D gives fewer poles); the first curve
// whose measured max radial error is <= tol is returned (verified_on_ladder, peer_fit.h).
//
// Inputs:
//   R                 the profile (closed or open)
//   deg_min, deg_max  the degrees OCCT may choose from, 1 <= deg_min <= deg_max <= 25 (3..3 for a
//                     cubic, 3..8 for its best)
//   tol               the tolerance ε, mm (> 0)
// Output:
//   the verified curve with its poles, degree, measured error and Tol3D (peer_tolerance); found =
//   false when no Tol3D of the ladder gave one (a fit that fails or throws Standard_Failure is
//   skipped).
PeerCurve occt_points_to_bspline(const PolarFunction& R, int deg_min, int deg_max, double tol);

}  // namespace polarform
