// Thinning by the base surface (Piegl & Tiller 2001, §3.3; spec P7): the base decomposed again at
// the thinning tolerance, then thin_by_blanket. Kept out of the build until decompose_surface
// (src/nurbs/surface_decomposition.cpp) is merged.
#include "src/fit/thinning.h"

namespace polarform {

// Piegl & Tiller 2001, §3.3 (second decomposition at ε_thin).
Thinning thin_by_base(const Eigen::Matrix3Xd& points, const NurbsSurface& base,
                      double tolerance_rel, SplitRule split) {
  const SurfaceDecomposition d = decompose_surface(base, {tolerance_rel, split});
  Thinning t = thin_by_blanket(points, d.blanket);
  t.tolerance = d.tolerance;
  return t;
}

}  // namespace polarform
