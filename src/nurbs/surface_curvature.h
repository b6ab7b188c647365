// Differential geometry of a NURBS surface at a parameter (MIT 13.472J §8.2.4, eqs. (8.37)–(8.39);
// do Carmo §3.3): the first and second fundamental forms E, F, G and L, M, N about the normal
// n = S_u × S_v / |S_u × S_v|, the Gaussian curvature K = (LN − M²)/(EG − F²), the mean curvature
// H = (EN − 2FM + GL) / (2(EG − F²)) (positive where the surface bends towards n), the principal
// curvatures H ± √(H² − K), and the absolute curvature |κ1| + |κ2|; and the reflection-line
// stripe value of a point (the light line its reflected view ray meets).
#pragma once

#include <Eigen/Core>

#include "src/nurbs/nurbs_surface.h"

namespace polarform {

struct SurfaceCurvature {
  double gaussian = 0.0, mean = 0.0;
  double k1 = 0.0, k2 = 0.0;  // principal curvatures, k1 >= k2
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  bool degenerate = false;  // S_u × S_v vanishes (a pole, a collapsed edge): values are NaN
  double absolute() const { return std::abs(k1) + std::abs(k2); }
};

SurfaceCurvature surface_curvature(const NurbsSurface& s, double u, double v);

// Reflection lines (MIT §8.2.4): parallel light lines of direction `line` in the plane
// {x : plane_normal·x = plane_offset}, a distance `spacing` apart, seen along the view direction
// `view` (from the eye towards the surface). The ray reflected at the point (r = e − 2(e·n)n) meets
// the plane at X; the value is (X·w)/spacing with w = plane_normal × line, so the lines are where
// it crosses an integer. NaN where the reflected ray runs parallel to the plane or away from it.
struct ReflectionLights {
  Eigen::Vector3d view, line, plane_normal;
  double plane_offset = 0.0, spacing = 1.0;
};
double reflection_line_value(const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                             const ReflectionLights& lights);

}  // namespace polarform
