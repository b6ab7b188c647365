// Measured continuity of fitted surfaces: across the seam of a closed surface (Bae 2002, §3.3.1:
// S(u, v_s) = S(u, v_e) and agreeing tangent planes) and at a degenerate pole (§3.3.2: the boundary
// collapsed to one point (3.11) with one tangent plane, the normal (3.12)
// n = S_u × S_uv / |S_u × S_uv| the same for every v).
#pragma once

#include <Eigen/Core>

#include "src/nurbs/nurbs_surface.h"

namespace polarform {

struct SeamReport {
  double gap = 0.0;           // max |S(u, v_s) − S(u, v_e)|
  double normal_angle = 0.0;  // max angle (rad) between the normals on the two sides
};

// Sampled at `samples` values of u (where the normal exists).
SeamReport seam_continuity(const NurbsSurface& s, int samples = 201);

struct PoleReport {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // mean of S(u_b, v)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // mean of the normals (3.12)
  double gap = 0.0;           // max |S(u_b, v) − point|: the G0 defect (3.11)
  double normal_spread = 0.0; // max angle (rad) between a normal (3.12) and their mean
};

// At the boundary u_b = front_u (at_start) or back_u, sampled at `samples` values of v.
PoleReport pole_continuity(const NurbsSurface& s, bool at_start, int samples = 201);

}  // namespace polarform
