// The angle–parameter relation of a unit-circle arc: rational quadratic Bezier (RQB) arcs and
// Blanc–Schlick quasi-uniform quartic arcs, and the α that makes the quartic arc nearly uniform.
// φ is the HALF arc angle (0 < φ ≤ π/2), η ∈ [0, 1] the arc's local parameter and ξ ∈ [0, 2φ] the
// polar angle measured from the arc start. The RQB relation also holds at φ = π/2 (a limit that
// cannot be built as an RQB curve, whose middle weight cos φ would vanish).
#pragma once

namespace polarform {

// Rounding slack (radians, and on η) accepted at angle and parameter limits before clamping: an
// arc built as start + π may exceed π by an ulp.
inline constexpr double kAngleSlack = 1e-12;

// The arc type a base circle is made of.
enum class ArcKind {
  rqb,      // rational quadratic Bezier arc, Bae 2002, eq. (2.4)
  quartic,  // Blanc–Schlick quasi-uniform rational quartic arc, Bae 2002, eq. (5.2)
};

// How the quartic arc's α is chosen: the smallest max angle deviation (DESIGN §4.3) or the thesis's
// formula (exactly uniform at η = 1/5 and 4/5).
enum class AlphaRule { minimax, printed };

// Knots of a base circle at its breakpoints: u_j = θ_j (angle) or u_j = j (unit, Bae (2.8)).
enum class ArcParametrization { angle, unit };

// α of (5.2) as printed; Bae 2002, eq. (5.2).
double printed_alpha(double half_angle);

// The minimax α of DESIGN §4.3 (a fitted equioscillation point k(φ) made exactly uniform).
double minimax_alpha(double half_angle);

double quartic_alpha(double half_angle, AlphaRule rule);

// η of the RQB arc whose point lies at angle ξ; Bae 2002, eq. (2.7) in the pole-free form of
// DESIGN §4.2. ξ must lie in [0, 2φ] (within kAngleSlack, then clamped).
double rqb_arc_parameter(double half_angle, double xi);

// ξ of the RQB arc point at η, the inverse of rqb_arc_parameter; Blanc & Schlick 1996 via (5.3)
// with s = η.
double rqb_arc_angle(double half_angle, double eta);

// ξ of the quartic arc point at η; Bae 2002, eq. (5.3).
double quartic_arc_angle(double half_angle, double alpha, double eta);

// η of the quartic arc point at angle ξ, the exact inverse of quartic_arc_angle: the RQB
// parameter s of ξ, then the root in [0, 1] of the quadratic s(η) = s of (5.3).
double quartic_arc_parameter(double half_angle, double alpha, double xi);

}  // namespace polarform
