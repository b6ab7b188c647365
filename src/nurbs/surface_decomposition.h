// Crack-free quadrilateral decomposition of a NURBS surface to a tolerance (Piegl & Tiller 2001,
// §3.1; spec P4): parameter rectangles are split at their midpoints until every sub-patch's control
// points lie within ε of the plane through its corners' centroid with normal d1 × d2 (d1, d2 the
// corner diagonals; the LSQ plane of the net where d1 × d2 vanishes) and — beyond the seed, which
// only bounds the distance along the normal — within ε of the bilinear patch of its corners at
// their Greville parameters (the in-plane part: curved edges, collapsed corners); the blanket is
// the full tensor grid of all split values, so it has no T-junctions, and a non-rational surface
// lies within 2ε of the bilinear quads of the blanket.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/nurbs_surface.h"

namespace polarform {

// The tensor grid of surface points S(u_a, v_b): vertex (a, b) in column a·v.size() + b; quad (a, b)
// spans [u_a, u_{a+1}] × [v_b, v_{b+1}].
struct SurfaceBlanket {
  std::vector<double> u, v;
  Eigen::Matrix3Xd points;
  int quads_u() const { return static_cast<int>(u.size()) - 1; }
  int quads_v() const { return static_cast<int>(v.size()) - 1; }
  int quads() const { return quads_u() * quads_v(); }
  int vertex(int a, int b) const { return a * static_cast<int>(v.size()) + b; }
};

// Which direction a non-flat rectangle is halved in: the seed's larger corner-to-corner extent, or
// the direction whose control-polygon rows/columns deviate more from their chords.
enum class SplitRule { extent, curvature };

struct DecompositionOptions {
  double tolerance_rel = 0.005;  // ε = tolerance_rel · diagonal of the control net's bounding box
  SplitRule split = SplitRule::extent;
};

struct SurfaceDecomposition {
  SurfaceBlanket blanket;
  double tolerance = 0.0;  // ε in mm
  int flatness_tests = 0;  // sub-patches tested
};

// Throws InputError for a bad tolerance, NumericalError when a span would fall below 1e-12 of the
// domain or the split depth would pass 40.
SurfaceDecomposition decompose_surface(const NurbsSurface& s, const DecompositionOptions& options);

}  // namespace polarform
