#include "designers/vessel/vessel_surfaces.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"
#include "src/nurbs/knot_insertion.h"
#include "src/nurbs/surface_of_revolution.h"

namespace polarform {

namespace {

const Eigen::Vector3d kOrigin = Eigen::Vector3d::Zero();
const Eigen::Vector3d kAxis = Eigen::Vector3d::UnitZ();

// The parameter where x(u) changes sign, by bisection; snapped to a knot within 1e-9 of the domain.
double axis_crossing(const NurbsCurve2d& c) {
  double a = c.front(), b = c.back();
  for (int k = 0; k < 200 && b - a > 0.0; ++k) {
    const double m = 0.5 * (a + b);
    if (m == a || m == b) break;
    (c.point(m).x() > 0 ? a : b) = m;
  }
  const double u = 0.5 * (a + b), slack = 1e-9 * (c.back() - c.front());
  for (double knot : c.knots())
    if (std::abs(knot - u) <= slack) return knot;
  return u;
}

// The part [front, u] of c (u inserted to full multiplicity; NURBS Book A5.1).
BSpline head_part(const BSpline& c, double u) {
  const int p = c.degree();
  const int existing = static_cast<int>(std::count(c.knots().begin(), c.knots().end(), u));
  const BSpline split = insert_knot(c, u, std::max(0, p - existing));
  const Knots& U = split.knots();
  const int first = static_cast<int>(std::find(U.begin(), U.end(), u) - U.begin());
  Knots knots(U.begin(), U.begin() + first + p);
  knots.push_back(u);
  return BSpline(p, std::move(knots), split.coefs().leftCols(first));
}

// z → 2 z_m − z for every control point, and the parameter reversed (u → a + b − u).
NurbsCurve3d mirrored_reversed(const NurbsCurve3d& c, double z_mirror) {
  Eigen::MatrixXd h = c.homogeneous().coefs().rowwise().reverse();
  for (Eigen::Index j = 0; j < h.cols(); ++j) h(2, j) = (2 * z_mirror - h(2, j) / h(3, j)) * h(3, j);
  Knots knots = c.knots();
  const double a = knots.front(), b = knots.back();
  std::reverse(knots.begin(), knots.end());
  for (double& k : knots) k = a + b - k;
  return NurbsCurve3d(BSpline(c.degree(), std::move(knots), h));
}

}  // namespace

// (x, z) homogeneous rows → (x, 0, z) in 3D.
NurbsCurve3d in_meridian_plane(const NurbsCurve2d& profile) {
  const BSpline& planar = profile.homogeneous();
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(4, planar.size());
  h.row(0) = planar.coefs().row(0);
  h.row(2) = planar.coefs().row(1);
  h.row(3) = planar.coefs().row(2);
  return NurbsCurve3d(BSpline(planar.degree(), planar.knots(), h));
}

VesselSurfaces vessel_surfaces(const NurbsCurve2d& profile, double length) {
  if (!(length > 0.0 && std::isfinite(length)))
    throw InputError("vessel surfaces: length " + to_text(length) + " mm, expected > 0");
  const Eigen::Vector2d start = profile.point(profile.front()), end = profile.point(profile.back());
  const double size = std::max(start.norm(), end.norm());
  if (!(start.x() > 0.0) || std::abs(start.y()) > 1e-9 * size || !(end.x() < 0.0))
    throw InputError("vessel surfaces: the profile must run from junction A (x > 0, z = 0) across "
                     "the axis to x < 0; it runs from (" + to_text(start.x()) + ", " +
                     to_text(start.y()) + ") to (" + to_text(end.x()) + ", " + to_text(end.y()) + ")");

  VesselSurfaces out;
  out.apex_parameter = axis_crossing(profile);
  BSpline half = head_part(profile.homogeneous(), out.apex_parameter);
  {  // the apex exactly on the axis (the bisection leaves it off by round-off)
    Eigen::MatrixXd h = half.coefs();
    h(0, h.cols() - 1) = 0.0;
    half = BSpline(half.degree(), half.knots(), h);
  }
  out.head_profile = NurbsCurve2d(half);
  const NurbsCurve3d head = in_meridian_plane(out.head_profile);
  out.head = revolve(head, kOrigin, kAxis);

  const Eigen::Vector3d junction = head.control_point(0);
  out.junction_radius = junction.x();
  const double z_mirror = junction.z() - length / 2;
  const NurbsCurve3d far = mirrored_reversed(head, z_mirror);
  out.far_head = revolve(far, kOrigin, kAxis);

  // The line carries the junction's weight at both ends, so the shared circles coincide in
  // homogeneous form too (a constant weight leaves the line non-rational).
  const Eigen::Vector3d bottom = far.control_point(far.size() - 1);
  const double w = head.weight(0);
  NurbsCurve3d::Points line{bottom, junction};
  out.cylinder = revolve(NurbsCurve3d(1, {0.0, 0.0, 1.0, 1.0}, line, {w, w}), kOrigin, kAxis);
  return out;
}

}  // namespace polarform
