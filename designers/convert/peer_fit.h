// What the conversion study's peer converters (issue 14) share: the dense samples of the contour
// r = R(θ) they are handed, the peer's curve with its measured error (PeerCurve), and the ladder of
// tolerances handed to a peer, each fit verified by polarform's own dense measurement
// (conversion_error.h) like polarform's curves. Used by occt_peer.cpp and sisl_peer.cpp.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <vector>

#include "designers/convert/polar_function.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct PeerCurve {
  bool found = false;             // some tolerance of the ladder gave a curve measured within tol
  int control_points = 0;         // of that curve as a clamped B-spline (0 when not found)
  int degree = 0;                 // its degree (the peer's choice where it chooses)
  double max_radial_error = 0.0;  // mm, measured against R
  double peer_tolerance = 0.0;  // mm, the tolerance handed to the peer (OCCT's Tol3D, SISL's eeps)
  NurbsCurve2d curve;           // its parameter mapped linearly onto [R.start, R.end]
};

// Samples handed to the peers: R(θ)(cos θ, sin θ) at `count` angles equally spaced over
// [R.start, R.end] (both ends included; the last is R.end exactly).
inline constexpr int kPeerSamples = 1441;
std::vector<Eigen::Vector2d> peer_contour_samples(const PolarFunction& R, int count = kPeerSamples);

// The tolerances handed to a peer, as multiples of ε: the peers check their tolerance at the
// samples only (or against the samples' polygon), and a looser one gives fewer control points.
inline constexpr double kPeerToleranceLadder[] = {2.0, 1.4, 1.0, 0.7, 0.5, 0.35, 0.25};

// verified_on_ladder(R, tol, fit)
//
// Calls fit(factor·tol) for the factors of kPeerToleranceLadder in turn and returns the first
// curve whose max radial error against R, measured densely (profile_error with 20000 points, at
// least samples_per_span in each span, maxima refined), is <= tol. fit returns nothing where the
// peer gives no curve. found = false when no tolerance of the ladder gave a verified curve.
PeerCurve verified_on_ladder(const PolarFunction& R, double tol,
                             const std::function<std::optional<NurbsCurve2d>(double)>& fit);

}  // namespace polarform
