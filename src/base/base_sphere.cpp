#include "src/base/base_sphere.h"

#include <string>

#include "src/error.h"

namespace polarform {

namespace {

BaseCircle checked_meridian(BaseCircle meridian) {
  const double front = meridian.breakpoints().front(), back = meridian.breakpoints().back();
  if (!(front >= -kAngleSlack && back <= std::numbers::pi + kAngleSlack))
    throw InputError("base sphere polar range [" + std::to_string(front) + ", " +
                     std::to_string(back) + "]: expected phi within [0, pi]");
  return meridian;
}

// Surface of revolution of the meridian (z, r) = (cos φ, sin φ), i.e. the circle's (x, y) read as
// (z, r), about the z axis: P^w_ij = (r^w_i a^w_jx, r^w_i a^w_jy, z^w_i a_jw, w_i a_jw);
// NURBS Book A8.1 in homogeneous form.
NurbsSurface revolve(const BaseCircle& meridian, const BaseCircle& azimuth) {
  const NurbsCurve2d& m = meridian.curve();
  const NurbsCurve2d& a = azimuth.curve();
  const Eigen::MatrixXd& M = m.homogeneous().coefs();
  const Eigen::MatrixXd& A = a.homogeneous().coefs();
  const int nu = m.size(), nv = a.size();
  Eigen::MatrixXd h(4, nu * nv);
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      h.col(i * nv + j) << M(1, i) * A(0, j), M(1, i) * A(1, j), M(0, i) * A(2, j), M(2, i) * A(2, j);
  return NurbsSurface(BSplineSurface(m.degree(), a.degree(), m.knots(), a.knots(), std::move(h)));
}

}  // namespace

BaseSphere::BaseSphere(BaseCircle meridian, BaseCircle azimuth)
    : meridian_(checked_meridian(std::move(meridian))), azimuth_(std::move(azimuth)),
      surface_(revolve(meridian_, azimuth_)) {}

BaseSphere::BaseSphere(ArcKind kind, double phi_start, double phi_end, double theta_start,
                       double theta_end, AlphaRule rule, ArcParametrization param, double max_sweep)
    : BaseSphere(BaseCircle::with_max_sweep(kind, phi_start, phi_end, max_sweep, rule, param),
                 BaseCircle::with_max_sweep(kind, theta_start, theta_end, max_sweep, rule, param)) {}

// Bae 2002, §3.1 Step 3.
Eigen::Vector2d BaseSphere::parameters(double phi, double theta) const {
  return {meridian_.parameter(phi), azimuth_.parameter(theta)};
}

Eigen::Vector2d BaseSphere::angles(double u, double v) const {
  return {meridian_.angle(u), azimuth_.angle(v)};
}

}  // namespace polarform
