#include "src/nurbs/surface_of_revolution.h"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "src/error.h"
#include "src/nurbs/error_text.h"

namespace polarform {

// NURBS Book A8.1 (MakeRevolvedSurf); the middle point of each arc is written in closed form
// (the tangent lines at the arc ends meet at radius r / cos(Δ/2) on the bisector).
NurbsSurface revolve(const NurbsCurve3d& profile, const Eigen::Vector3d& axis_point,
                     const Eigen::Vector3d& axis_direction, double angle) {
  if (!axis_point.allFinite())
    throw InputError("revolve: axis point must be finite");
  if (!axis_direction.allFinite() || axis_direction.norm() == 0.0)
    throw InputError("revolve: axis direction must be a finite non-zero vector");
  if (!(angle > 0.0 && angle <= 2 * std::numbers::pi))
    throw InputError("revolve: angle " + to_text(angle) + " rad outside (0, 2π]");

  const int arcs = angle <= std::numbers::pi / 2       ? 1
                   : angle <= std::numbers::pi         ? 2
                   : angle <= 3 * std::numbers::pi / 2 ? 3
                                                       : 4;
  const double step = angle / arcs, middle_weight = std::cos(step / 2);
  const bool full_turn = angle == 2 * std::numbers::pi;

  Knots U(2 * arcs + 4);
  for (int k = 0; k < 3; ++k) {
    U[k] = 0.0;
    U[2 * arcs + 1 + k] = 1.0;
  }
  for (int a = 1; a < arcs; ++a) U[2 * a + 1] = U[2 * a + 2] = static_cast<double>(a) / arcs;

  const Eigen::Vector3d T = axis_direction.normalized();
  const int nu = 2 * arcs + 1, nv = profile.size();
  NurbsSurface::Points points(static_cast<std::size_t>(nu) * nv);
  std::vector<double> weights(points.size());
  for (int j = 0; j < nv; ++j) {
    const Eigen::Vector3d P = profile.control_point(j);
    const double w = profile.weight(j);
    const Eigen::Vector3d O = axis_point + T.dot(P - axis_point) * T;  // foot on the axis
    Eigen::Vector3d X = P - O;
    const double r = X.norm();
    if (r > 0.0) X /= r;
    const Eigen::Vector3d Y = T.cross(X);
    const auto at = [&](double radius, double a) -> Eigen::Vector3d {
      return O + radius * (std::cos(a) * X + std::sin(a) * Y);
    };
    for (int i = 0; i < nu; ++i) {
      const bool end_of_arc = i % 2 == 0;
      const double a = i * step / 2;
      const std::size_t k = static_cast<std::size_t>(i) * nv + j;
      points[k] = end_of_arc ? at(r, a) : at(r / middle_weight, a);
      weights[k] = end_of_arc ? w : w * middle_weight;
    }
    points[0 * nv + j] = P;
    if (full_turn) points[static_cast<std::size_t>(nu - 1) * nv + j] = P;
  }
  return NurbsSurface(2, profile.degree(), std::move(U), profile.knots(), points, weights);
}

}  // namespace polarform
