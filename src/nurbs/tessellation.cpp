#include "src/nurbs/tessellation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"

namespace polarform {

namespace {

template <int Dim>
CurveTessellation<Dim> tessellate_curve(const NurbsCurve<Dim>& curve, int count) {
  CurveTessellation<Dim> out;
  out.parameters = tessellation_parameters(curve.knots(), curve.front(), curve.back(), count);
  out.points.reserve(out.parameters.size());
  for (double t : out.parameters) out.points.push_back(curve.point(t));  // NURBS Book A4.1
  return out;
}

// S_u × S_v made unit, or zero where the surface degenerates: a derivative that vanishes against
// the other (a pole: round-off, not an exact zero, in a rational surface) or two that are parallel.
NurbsSurface::Point unit_normal(const NurbsSurface::Point& su, const NurbsSurface::Point& sv) {
  constexpr double kDegenerate = 1e-9;
  const double a = su.norm(), b = sv.norm();
  const NurbsSurface::Point n = su.cross(sv);
  if (std::min(a, b) <= kDegenerate * std::max(a, b) || n.norm() <= kDegenerate * a * b)
    return NurbsSurface::Point::Zero();
  return n.normalized();
}

}  // namespace

// At a knot of multiplicity m the curve is only C^(p−m) (NURBS Book P2.5): sample it exactly there.
std::vector<double> tessellation_parameters(const Knots& knots, double a, double b, int count) {
  if (count < 1)
    throw InputError("tessellation: " + std::to_string(count) + " steps, expected at least 1");
  if (!(std::isfinite(a) && std::isfinite(b) && a < b))
    throw InputError("tessellation: parameter range [" + std::to_string(a) + ", " +
                     std::to_string(b) + "], expected finite a < b");
  std::vector<double> exact{a};  // the ends and the interior knots, kept as they are
  for (const Breakpoint& k : breakpoints(knots))
    if (k.value > a && k.value < b) exact.push_back(k.value);
  exact.push_back(b);
  const double tolerance = 1e-12 * (b - a);
  std::vector<double> out;
  out.reserve(exact.size() + count);
  auto next = exact.begin();
  for (int k = 1; k < count; ++k) {
    const double t = a + (b - a) * k / count;
    while (*next < t - tolerance) out.push_back(*next++);
    if (std::abs(*next - t) > tolerance) out.push_back(t);
  }
  out.insert(out.end(), next, exact.end());
  return out;
}

CurveTessellation<2> tessellate(const NurbsCurve2d& curve, int count) {
  return tessellate_curve(curve, count);
}

CurveTessellation<3> tessellate(const NurbsCurve3d& curve, int count) {
  return tessellate_curve(curve, count);
}

SurfaceTessellation tessellate(const NurbsSurface& surface, int count_u, int count_v) {
  SurfaceTessellation out;
  out.u = tessellation_parameters(surface.knots_u(), surface.front_u(), surface.back_u(), count_u);
  out.v = tessellation_parameters(surface.knots_v(), surface.front_v(), surface.back_v(), count_v);
  const std::size_t nu = out.u.size(), nv = out.v.size();
  out.points.resize(nu * nv);
  out.normals.resize(nu * nv);
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      // NURBS Book A4.4: the point and its first derivatives; the normal S_u × S_v, unit.
      const NurbsSurface::Points d = surface.derivatives(out.u[i], out.v[j], 1);
      out.points[i * nv + j] = d[0];
      out.normals[i * nv + j] = unit_normal(d[2], d[1]);
    }
  // A pole has no normal of its own: the neighbour's along u stands in for it, or, where the
  // pole's row runs along u (a revolved profile's point on the axis), the neighbour's along v.
  const auto neighbour = [](std::size_t k, std::size_t n) { return k + 1 < n ? k + 1 : k - 1; };
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j)
      if (out.normals[i * nv + j] == NurbsSurface::Point::Zero())
        out.normals[i * nv + j] = out.normals[neighbour(i, nu) * nv + j];
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j)
      if (out.normals[i * nv + j] == NurbsSurface::Point::Zero())
        out.normals[i * nv + j] = out.normals[i * nv + neighbour(j, nv)];
  return out;
}

}  // namespace polarform
