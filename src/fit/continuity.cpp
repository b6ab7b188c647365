#include "src/fit/continuity.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

namespace polarform {

namespace {

double angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace

SeamReport seam_continuity(const NurbsSurface& s, int samples) {
  SeamReport r;
  const double v0 = s.front_v(), v1 = s.back_v();
  auto u_at = [&](int a) { return s.front_u() + (s.back_u() - s.front_u()) * a / (samples - 1); };
  double scale = 0.0;
  for (int a = 0; a < samples; ++a) scale = std::max(scale, s.point(u_at(a), v0).norm());
  for (int a = 0; a < samples; ++a) {
    const double u = u_at(a);
    r.gap = std::max(r.gap, (s.point(u, v0) - s.point(u, v1)).norm());
    const NurbsSurface::Points d0 = s.derivatives(u, v0, 1), d1 = s.derivatives(u, v1, 1);
    const Eigen::Vector3d n0 = d0[2].cross(d0[1]), n1 = d1[2].cross(d1[1]);
    // Skip degenerate points (a pole), where the normal is a limit, not a cross product.
    if (n0.norm() <= 1e-9 * scale * scale || n1.norm() <= 1e-9 * scale * scale) continue;
    r.normal_angle = std::max(r.normal_angle, angle(n0, n1));
  }
  return r;
}

// Bae 2002, eqs. (3.11)-(3.12).
PoleReport pole_continuity(const NurbsSurface& s, bool at_start, int samples) {
  PoleReport r;
  const double ub = at_start ? s.front_u() : s.back_u();
  std::vector<Eigen::Vector3d> pts, normals;
  for (int a = 0; a < samples; ++a) {
    const double v = s.front_v() + (s.back_v() - s.front_v()) * a / (samples - 1);
    const NurbsSurface::Points d = s.derivatives(ub, v, 2);  // index k·3 + l
    pts.push_back(d[0]);
    const Eigen::Vector3d n = d[3].cross(d[4]);
    if (n.norm() > 0.0) normals.push_back(n.normalized());
  }
  for (const auto& p : pts) r.point += p / static_cast<double>(pts.size());
  for (const auto& p : pts) r.gap = std::max(r.gap, (p - r.point).norm());
  for (const auto& n : normals) r.normal += n;
  if (r.normal.norm() > 0.0) r.normal.normalize();
  for (const auto& n : normals) r.normal_spread = std::max(r.normal_spread, angle(n, r.normal));
  return r;
}

}  // namespace polarform
