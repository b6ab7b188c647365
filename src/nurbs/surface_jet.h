// The second-order jet of a NURBS surface at one parameter: S, S_u, S_v, S_uu, S_uv, S_vv, computed
// without allocating (stack workspaces), for inner loops such as Newton point inversion that
// evaluate it millions of times. NURBS Book A3.6 and A4.4 specialised to d = 2.
#pragma once

#include <Eigen/Core>

#include "src/nurbs/nurbs_surface.h"

namespace polarform {

struct SurfaceJet {
  Eigen::Vector3d s, su, sv, suu, suv, svv;
};

SurfaceJet surface_jet(const NurbsSurface& surface, double u, double v);

}  // namespace polarform
