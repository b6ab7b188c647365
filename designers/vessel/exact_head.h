// The standard heads exactly: their meridians as rational quadratic NURBS — every circular or
// elliptic arc of at most 90° is one rational quadratic segment (NURBS Book §7.5) — joined with the
// heads' own tangent continuity at double knots, from junction A (θ = 0) over the apex to junction
// B (θ = π) in the vessel's meridian plane (x radial, z axial; vessel_surfaces.h). Revolved, the
// head is an exact (2, 2) surface. The closed forms they represent are head_shape's.
#pragma once

#include "designers/vessel/head_preset.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct ExactHead {
  HeadShape shape;              // the closed form: pieces, depth, curvature jumps
  NurbsCurve2d meridian;        // degree 2, junction A → apex → junction B, (x, z)
  // Rational quadratic segments, on [i, i + 1] each (2 per half for a torispherical head and a
  // conical one with a knuckle): the apex is at the parameter arcs / 2.
  int arcs = 0;
};

// Hemispherical: two circular quarters; ellipsoidal: two elliptic quarters (semi-axes radius and
// radius/ratio); torispherical: knuckle, crown to the apex, and mirrored; conical: knuckle (if any)
// and the cone's straight meridian to the apex as a degree-2 line, and mirrored. Throws InputError
// for the parameters head_shape rejects.
ExactHead exact_head(const HeadPreset& preset, double radius);

// The largest |ρ − R(θ)| of the meridian against the closed form R(θ) of `shape`, at `samples`
// equally spaced parameters between every two of its breakpoints (mm): the measured error.
double exact_head_deviation(const NurbsCurve2d& meridian, const HeadShape& shape, int samples);

}  // namespace polarform
