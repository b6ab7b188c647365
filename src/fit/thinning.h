// Thinning by the base surface's geometry (Piegl & Tiller 2001, §3.3; spec P7): the base is
// decomposed again at the thinning tolerance and each blanket vertex keeps its nearest data point
// (ring search of a uniform grid), so curved regions keep more points than flat ones.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/surface_decomposition.h"

namespace polarform {

struct Thinning {
  std::vector<int> kept;    // indices of the kept points, increasing
  int vertices = 0;         // blanket vertices of the thinning decomposition
  double mean_rings = 0.0;  // mean index of the last ring searched per vertex (0: its own cell)
  double tolerance = 0.0;   // ε_thin in mm
};

// Marks the data point nearest (3D) to every vertex of `blanket` (P&T's ring search in a uniform
// grid of the points); tolerance is left 0. Throws InputError for no points or an empty blanket.
Thinning thin_by_blanket(const Eigen::Matrix3Xd& points, const SurfaceBlanket& blanket);

// Decomposes `base` at tolerance_rel (relative to its control net's diagonal, as
// decompose_surface) and marks the data point nearest (3D) to every vertex.
Thinning thin_by_base(const Eigen::Matrix3Xd& points, const NurbsSurface& base,
                      double tolerance_rel, SplitRule split = SplitRule::extent);

}  // namespace polarform
