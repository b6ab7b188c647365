#include "src/nurbs/surface_curvature.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "src/nurbs/surface_jet.h"

namespace polarform {

SurfaceCurvature surface_curvature(const NurbsSurface& s, double u, double v) {
  const SurfaceJet j = surface_jet(s, u, v);
  SurfaceCurvature c;
  const Eigen::Vector3d cross = j.su.cross(j.sv);
  const double E = j.su.squaredNorm(), F = j.su.dot(j.sv), G = j.sv.squaredNorm();
  const double det = E * G - F * F;
  if (!(cross.norm() > 1e-12 * std::max(E, G)) || !(det > 0)) {
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    c.gaussian = c.mean = c.k1 = c.k2 = nan;
    c.degenerate = true;
    return c;
  }
  c.normal = cross.normalized();
  const double L = j.suu.dot(c.normal), M = j.suv.dot(c.normal), N = j.svv.dot(c.normal);
  c.gaussian = (L * N - M * M) / det;
  c.mean = (E * N - 2 * F * M + G * L) / (2 * det);
  const double root = std::sqrt(std::max(0.0, c.mean * c.mean - c.gaussian));
  c.k1 = c.mean + root;
  c.k2 = c.mean - root;
  return c;
}

double reflection_line_value(const Eigen::Vector3d& point, const Eigen::Vector3d& normal,
                             const ReflectionLights& l) {
  const Eigen::Vector3d e = l.view.normalized();
  const Eigen::Vector3d r = e - 2 * e.dot(normal) * normal;
  const Eigen::Vector3d m = l.plane_normal.normalized();
  const double along = m.dot(r);
  const double t = (l.plane_offset - m.dot(point)) / along;
  if (!(std::abs(along) > 1e-12) || !(t > 0)) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector3d x = point + t * r;
  return x.dot(m.cross(l.line).normalized()) / l.spacing;
}

}  // namespace polarform
