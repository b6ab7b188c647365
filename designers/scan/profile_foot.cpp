#include "designers/scan/profile_foot.h"

#include <cmath>

namespace polarform {

ProfileFeet::ProfileFeet(const PolarCurveFit& fit)
    : fit_(fit),
      F_(0, fit.F.degree(), Knots{0.0, 1.0}, fit.F.knots(), fit.F.spline().coefs()),
      geometry_(ProductGeometry::polar(F_, fit.base)) {}

ProfileFoot ProfileFeet::operator()(const Eigen::Vector2d& q) const {
  const Eigen::Vector2d local = q - fit_.centre;
  const double u0 = fit_.base.parameter(std::atan2(local.y(), local.x()));
  const FootPoint f = geometry_.foot_point(Eigen::Vector3d(local.x(), local.y(), 0.0), 0.0, u0);
  double S[3], Su[3], Sv[3];
  geometry_.evaluate(0.0, f.v, S, Su, Sv);
  ProfileFoot out;
  out.u = f.v;
  out.point = Eigen::Vector2d(S[0], S[1]) + fit_.centre;
  out.normal = Eigen::Vector2d(Sv[1], -Sv[0]).normalized();
  if (out.normal.dot(Eigen::Vector2d(S[0], S[1])) < 0) out.normal = -out.normal;
  out.distance = f.distance;
  return out;
}

}  // namespace polarform
