// Moving frames along a spine curve for generalized cylinders and pipes (Patrikalakis & Maekawa,
// MIT 13.472J §8.3, Figs. 8.7–8.8): Frenet (X = n, Y = b; undefined on straight parts, flips at
// inflections), fixed (a constant X made orthogonal to the tangent; for a planar spine Y is the
// plane normal) and rotation-minimising (the double-reflection method, Wang, Jüttler, Zheng & Liu
// 2008).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/nurbs_curve.h"

namespace polarform {

enum class FrameRule { rmf, frenet, fixed };

struct SpineFrame {
  double t = 0.0;
  Eigen::Vector3d point, tangent, x, y;  // tangent, x, y orthonormal and right-handed
};

// Frames at the parameters ts (increasing, inside the spine's domain). `initial_x` (optional) is
// the first frame's x direction before it is made orthogonal to the tangent (rmf) or the constant
// X projected on every normal plane (fixed); else it is chosen from the spine (the principal
// normal where defined, else the coordinate axis most orthogonal to the tangent), and the fixed
// rule on a planar spine keeps y = the plane normal. The rmf integrates between the requested
// parameters in at least 64 steps, and enough that the tangent turns by at most 2e-3 rad per
// step. Throws InputError for Frenet where the curvature vanishes, a spine that is not regular
// at a requested parameter, a fixed X parallel to a tangent, or ts empty, unordered or outside.
std::vector<SpineFrame> spine_frames(const NurbsCurve3d& spine, const std::vector<double>& ts,
                                     FrameRule rule, const Eigen::Vector3d* initial_x = nullptr);

}  // namespace polarform
