// Parameters of scattered points on a base surface by projection onto its quad blanket (Piegl &
// Tiller 2001, §3.2, §3.4; spec P6): each point is matched with its nearest quad — by the true 3D
// distance to the bilinear quad at clamped (s, t) ∈ [0, 1]² (the seed's plane-distance rule lets far
// quads win) — found through a 3D grid of quad boxes searched in rings (default) or the seed's 2D
// grid in the maximum-area plane; (s, t) come from inverting the bilinear map, then the parameters
// are optionally polished by Newton on the base surface to the exact foot point.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/nurbs_surface.h"
#include "src/nurbs/surface_decomposition.h"

namespace polarform {

// grid3d: quads binned by their 3D boxes, cell = median quad diagonal (the default; no
// projectability needed). plane: the seed's 2D grid in the maximum-area plane, cell =
// sqrt(x_L·y_L / vertices), refused on folds; it is searched point by point in rings like grid3d
// (the seed loops over quads instead), which gives every point its nearest quad, also outside all
// projected quads.
enum class PatchSearch { grid3d, plane };

struct PatchSearchOptions {
  PatchSearch search = PatchSearch::grid3d;
  bool polish = true;  // Newton on the base surface from the quad parameters
  int threads = 2;
};

struct PatchSearchStats {
  int cells = 0;                   // grid cells
  long long point_quad_tests = 0;  // quad projections evaluated
  long long brute_force_tests = 0; // #quads · #points
  int clamped_points = 0;          // points whose nearest quad needed clamping (outside every quad)
  bool polished = false;
  int folded_triangles = 0;        // plane search: from the fold check (0 for grid3d)
};

struct PatchParameters {
  Eigen::VectorXd u, v;         // parameters on the base surface
  Eigen::VectorXd distance;     // |Q − S(u, v)| on the base surface (after the polish)
  std::vector<char> clamped;    // 1 where (s, t) was clamped to the quad
  PatchSearchStats stats;
};

// The base surface must be the one the blanket was decomposed from. Throws InputError when the
// plane search is asked for a folded blanket (naming the folded triangle count and suggesting
// grid3d).
PatchParameters parametrize_on_blanket(const Eigen::Matrix3Xd& points, const NurbsSurface& base,
                                       const SurfaceBlanket& blanket,
                                       const PatchSearchOptions& options = {});

}  // namespace polarform
