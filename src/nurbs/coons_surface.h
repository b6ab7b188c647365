// Coons base surfaces of a boundary loop (Piegl & Tiller 2001, §2.1–2.2; spec P1–P2): the Boolean
// sum S = L_u + L_v − T of two lofts and the tensor-product interpolant of the corners, built
// exactly on control points after making the three surfaces compatible (common_basis).
#pragma once

#include "src/nurbs/nurbs_surface.h"
#include "src/nurbs/patch_boundary.h"

namespace polarform {

// Bilinearly blended Coons patch (P&T §2.1): L_u, L_v ruled surfaces between opposite curves, T the
// bilinear patch of the corners. Degree (max(p, 1), max(q, 1)), domain [0, 1]². Throws InputError
// for a rational boundary.
NurbsSurface bilinear_coons(const PatchBoundary& b);

// The cross-boundary derivatives of a bicubically blended Coons patch (P&T §2.2): du0(v) =
// S_u(0, v), du1(v) = S_u(1, v) (same degree and knots as v0/v1), dv0(u) = S_v(u, 0), dv1(u) =
// S_v(u, 1) (same degree and knots as u0/u1).
struct CrossDerivatives {
  NurbsCurve3d du0, du1, dv0, dv1;
};

// Bicubically blended Coons patch (P&T §2.2): cubic Hermite blends H1..H4 of the boundary curves and
// cross derivatives, minus the bicubic Hermite interpolant T of the corner points, tangents and
// twists (the twists taken from the derivatives of the cross-derivative curves, mean of the two
// when they differ). Degree (max(3, p), max(3, q)), domain [0, 1]².
NurbsSurface bicubic_coons(const PatchBoundary& b, const CrossDerivatives& d);

}  // namespace polarform
