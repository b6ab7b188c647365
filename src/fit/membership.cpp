#include "src/fit/membership.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "src/error.h"
#include "src/fit/product_geometry.h"

namespace polarform {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// θ of the local point on the base circle, or false when it lies outside an open range.
bool azimuth_in_range(const BaseCircle& c, double x, double y, double& theta) {
  const double t0 = c.breakpoints().front(), t1 = c.breakpoints().back();
  theta = std::atan2(y, x);
  theta -= kTwoPi * std::floor((theta - t0) / kTwoPi);
  return c.closed() || theta <= t1 + kAngleSlack;
}

void check_tolerance(double tol) {
  if (!(tol >= 0.0) || !std::isfinite(tol))
    throw InputError("point membership: tolerance " + std::to_string(tol) + ", expected a finite value >= 0");
}

MembershipResult decide(const ProductGeometry& g, const Eigen::Vector3d& local, double u, double v,
                        double range, double tol) {
  MembershipResult r;
  r.radial = range - g.function(u, v);
  r.distance = g.foot_point(local, u, v).distance;
  r.where = std::abs(r.distance) <= tol ? Membership::on : r.radial < 0 ? Membership::inside : Membership::outside;
  return r;
}

}  // namespace

MembershipResult classify_point(const SphericalFit& fit, const Eigen::Vector3d& point, double tol) {
  check_tolerance(tol);
  const Eigen::Vector3d p = fit.frame.frame.to_local(point);
  const double rxy = std::hypot(p.x(), p.y()), rho = std::hypot(rxy, p.z());
  if (rho == 0.0) return {Membership::inside, -fit.F.coefs().minCoeff(), -fit.F.coefs().minCoeff()};
  const double phi = std::atan2(rxy, p.z());
  const BaseCircle& m = fit.base.meridian();
  double theta;
  if (phi < m.breakpoints().front() - kAngleSlack || phi > m.breakpoints().back() + kAngleSlack ||
      !azimuth_in_range(fit.base.azimuth(), p.x(), p.y(), theta))
    return {};
  const Eigen::Vector2d uv = fit.base.parameters(std::clamp(phi, m.breakpoints().front(), m.breakpoints().back()), theta);
  return decide(ProductGeometry::spherical(fit.F, fit.base), p, uv[0], uv[1], rho, tol);
}

MembershipResult classify_point(const CylindricalFit& fit, const Eigen::Vector3d& point, double tol) {
  check_tolerance(tol);
  const Eigen::Vector3d p = fit.frame.frame.to_local(point);
  const double r = std::hypot(p.x(), p.y());
  const double z0 = fit.base.z_start(), z1 = fit.base.z_end();
  if (p.z() < z0 || p.z() > z1) return {};
  if (r == 0.0) return {Membership::inside, -fit.F.coefs().minCoeff(), -fit.F.coefs().minCoeff()};
  double theta;
  if (!azimuth_in_range(fit.base.azimuth(), p.x(), p.y(), theta)) return {};
  const Eigen::Vector2d uv = fit.base.parameters(theta, p.z());
  return decide(ProductGeometry::cylindrical(fit.F, fit.base), p, uv[0], uv[1], r, tol);
}

}  // namespace polarform
