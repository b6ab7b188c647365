// The vessel's NURBS surfaces from the converted head profile: the head (the A half of R(θ)
// revolved), the cylindrical shell and the mirrored far head, all exact surfaces of revolution
// (NURBS Book A8.1) that share their junction circles. The geometry convention is stated at
// VesselSurfaces below.
#pragma once

#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

// Geometry convention (world frame, mm):
//  - the vessel axis is the z axis and every meridian lies in the plane y = 0 with x radial;
//  - the head's polar origin (Bae 2002, Fig. 5.6) is the world origin, on the axis in the plane of
//    junction A; θ turns from +x towards +z, so R(θ) is the point (x, z) = R(θ)(cos θ, sin θ):
//    junction A (θ = 0) at (R(0), 0), the apex (θ = π/2) at (0, R(π/2)), junction B (θ = π) at
//    (−R(π), 0) — the same head's other side in the section. The converter's 2D curve (x, y) is
//    read as (x, z);
//  - the head surface revolves the A half, θ in [0, π/2] (junction A to the apex), a full turn
//    about z (a profile that is not symmetric about θ = π/2 has its B half unused);
//  - the cylinder continues junction A's circle from z = 0 down to z = −length;
//  - the far head is the head mirrored in the plane z = −length/2.
// u runs around the axis (u in [0, 1], counter-clockwise about +z from the half-plane y = 0,
// x > 0), v along the meridian in +z (far apex → far junction, cylinder bottom → top, junction A →
// apex), so S_u × S_v points out of the vessel; neighbouring surfaces share their circles' control
// points exactly.
struct VesselSurfaces {
  NurbsCurve2d head_profile;  // the A half, junction A → apex, in (x, z)
  double apex_parameter = 0.0;   // the profile parameter where it crosses the axis
  double junction_radius = 0.0;  // x of junction A, mm: the cylinder's radius
  NurbsSurface head;      // z >= 0
  NurbsSurface cylinder;  // −length <= z <= 0
  NurbsSurface far_head;  // z <= −length
};

// The meridian curve (x, z) of the convention below as the 3D curve (x, 0, z), exactly.
NurbsCurve3d in_meridian_plane(const NurbsCurve2d& profile);

// `profile` is the converted R(θ) over θ in [0, π] (it starts at junction A on the +x axis and crosses
// the axis once). Throws InputError unless length > 0, the profile starts at x > 0 with |z| within
// 1e-9 of its size and ends at x < 0.
VesselSurfaces vessel_surfaces(const NurbsCurve2d& profile, double length);

}  // namespace polarform
