// The cap surface that closes the hole of a closed spherical surface at a pole with a tangent
// plane of its own (Bae 2002, §3.3.2 Steps 1–4 and Appendix D.2): quintic connecting curves across
// the hole between opposite v-nodes, G2 to the surface (3.16)-(3.17); scale factors α*, β* making
// their midpoints agree (3.18), (D.11); the degenerate point p* (3.20) and normal n* (3.21); the
// curves split at t = 1/2 and their first three control points moved to p*, onto the tangent
// plane, and to minimum bending; and the tensor-product cap of degree (5, q) interpolating them at
// the nodes (3.22)-(3.24).
#pragma once

#include <Eigen/Core>

#include "src/fit/continuity.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

struct PoleCap {
  NurbsSurface surface;  // degree (5, q): u = 0 at the pole, u = 1 on the surface's boundary
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // p*, eq. (3.20)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // n*, eq. (3.21), pointing away from the origin
  double alpha = 0.0, beta = 0.0;                    // α*, β* of (D.11)
  double boundary_gap = 0.0;           // max distance between the cap's and the surface's boundary
  double boundary_normal_angle = 0.0;  // max angle (rad) between their tangent planes there
  PoleReport pole;                     // G0 gap and normal spread (3.12) at p*
};

// The cap on the boundary u = front_u (at_start) or back_u of s, which must be closed in v with
// Greville nodes that pair up half a period apart (v-knots symmetric as in (3.15), with the middle
// break of full multiplicity, as a product with a square-based base circle has). The origin of s's
// coordinates must lie inside the body (it orients n*). Throws InputError otherwise.
//
// Two deliberate departures from the thesis: (3.22) weights every node by W(u_b, v_k), the boundary
// curve's own weight there (with the control weights w_k the cap's boundary would not reproduce the
// surface's); and (3.18) gains 1e-6 times the connecting curves' bending energy, which decides α, β
// when (D.11) is singular (a surface of revolution, where every α, β meet at one midpoint).
PoleCap build_pole_cap(const NurbsSurface& s, bool at_start);

}  // namespace polarform
