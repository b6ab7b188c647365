#include "src/base/base_cylinder.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"

namespace polarform {

namespace {

// Extrusion of the azimuth circle from zs to ze: P^w_ij = (a^w_jx, a^w_jy, z_i a_jw, a_jw);
// Bae 2002, eq. (3.7).
NurbsSurface extrude(const BaseCircle& azimuth, double zs, double ze) {
  if (!(std::isfinite(zs) && std::isfinite(ze) && zs < ze))
    throw InputError("base cylinder height range [" + std::to_string(zs) + ", " +
                     std::to_string(ze) + "]: expected finite z_start < z_end");
  const NurbsCurve2d& a = azimuth.curve();
  const Eigen::MatrixXd& A = a.homogeneous().coefs();
  const int nv = a.size();
  Eigen::MatrixXd h(4, 2 * nv);
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < nv; ++j)
      h.col(i * nv + j) << A(0, j), A(1, j), (i == 0 ? zs : ze) * A(2, j), A(2, j);
  return NurbsSurface(BSplineSurface(1, a.degree(), {0.0, 0.0, 1.0, 1.0}, a.knots(), std::move(h)));
}

}  // namespace

BaseCylinder::BaseCylinder(BaseCircle azimuth, double z_start, double z_end)
    : azimuth_(std::move(azimuth)), z_start_(z_start), z_end_(z_end),
      surface_(extrude(azimuth_, z_start_, z_end_)) {}

BaseCylinder::BaseCylinder(ArcKind kind, double theta_start, double theta_end, double z_start,
                           double z_end, AlphaRule rule, ArcParametrization param,
                           double max_sweep)
    : BaseCylinder(BaseCircle::with_max_sweep(kind, theta_start, theta_end, max_sweep, rule, param),
                   z_start, z_end) {}

// Bae 2002, §3.2: u = (z − zs)/(ze − zs), v by (2.7)–(2.8).
Eigen::Vector2d BaseCylinder::parameters(double theta, double z) const {
  const double u = (z - z_start_) / (z_end_ - z_start_);
  if (!(u >= -1e-12 && u <= 1.0 + 1e-12))
    throw InputError("base cylinder height z " + std::to_string(z) + ": expected a value in [" +
                     std::to_string(z_start_) + ", " + std::to_string(z_end_) + "]");
  return {std::clamp(u, 0.0, 1.0), azimuth_.parameter(theta)};
}

Eigen::Vector2d BaseCylinder::angles_height(double u, double v) const {
  if (!(u >= -1e-12 && u <= 1.0 + 1e-12))
    throw InputError("base cylinder parameter u " + std::to_string(u) + ": expected a value in [0, 1]");
  return {azimuth_.angle(v), z_start_ + std::clamp(u, 0.0, 1.0) * (z_end_ - z_start_)};
}

}  // namespace polarform
