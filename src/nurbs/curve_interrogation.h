// Interrogation of planar NURBS curves (Patrikalakis & Maekawa, MIT 2.158J lecture 8; spec M2):
// the jump of a derivative across every interior knot — the fairness measure, zero where the
// curve is as smooth there as its degree allows — the signed curvature, and the inflections, found
// as the sign changes of det(Pʷ, Pʷ′, Pʷ″) of the homogeneous curve, isolated per Bézier segment
// by Bernstein root isolation (Lane & Riesenfeld 1981) and refined by bisection.
#pragma once

#include <vector>

#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct KnotJump {
  double u;     // the interior knot (breakpoint)
  double jump;  // |C^(k)(u+) − C^(k)(u−)|, from the one-sided Bézier segments (exact)
};

// The jump of the k-th derivative (1 <= k <= degree) at every interior breakpoint, in order.
// Throws InputError for k outside [1, degree].
std::vector<KnotJump> derivative_jumps(const NurbsCurve2d& curve, int k);

// The signed curvature (C′ × C″)/|C′|³ at u, 1/mm: > 0 where the curve turns counter-clockwise.
double signed_curvature(const NurbsCurve2d& curve, double u);

// dκ/du at u, 1/mm per unit of u: ((C′ × C‴)|C′|² − 3 (C′ × C″)(C′ · C″)) / |C′|⁵ — where κ′ jumps
// at a knot is where a fairing should act first (spec M2).
double curvature_derivative(const NurbsCurve2d& curve, double u);

// The parameters where the signed curvature changes sign, in increasing order (a root of
// det(Pʷ, Pʷ′, Pʷ″) where it does not change sign is a flat point, not an inflection; nor is a
// zero within 1e-9 of a segment at the curve's own ends, e.g. a natural cubic's end).
std::vector<double> inflections(const NurbsCurve2d& curve);

}  // namespace polarform
