#include "designers/scan/follower_inversion.h"

#include <cmath>
#include <numbers>

#include "src/error.h"
#include "designers/scan/profile_foot.h"

namespace polarform {

namespace {

double wrap(double a) {
  const double t = std::fmod(a, 2 * std::numbers::pi);
  return t < 0 ? t + 2 * std::numbers::pi : t;
}

}  // namespace

FollowerSamples invert_follower(const PolarCurveFit& contour, const Eigen::Matrix2Xd& points,
                                const Follower& f, Rotation rotation) {
  const int sigma = sense(rotation);
  const ProfileFeet feet(contour);
  FollowerSamples out;
  out.theta.resize(points.cols());
  out.height.resize(points.cols());
  for (Eigen::Index k = 0; k < points.cols(); ++k) {
    const Eigen::Vector2d c = points.col(k);
    const Eigen::Vector2d n = feet(c).normal;
    if (f.kind == FollowerKind::FlatFaced) {
      // The face normal +y equals the contour normal turned by σθ.
      out.theta[k] = wrap(sigma * (std::numbers::pi / 2 - std::atan2(n.y(), n.x())));
      out.height[k] = c.dot(n);
      continue;
    }
    const Eigen::Vector2d p =
        f.kind == FollowerKind::Roller ? Eigen::Vector2d(c + f.roller_radius * n) : c;
    const double rho = p.norm(), e = f.offset;
    if (!(rho > std::abs(e)))
      throw InputError("follower inversion: a pitch point lies " + std::to_string(rho) +
                       " mm from the centre, within the follower offset |e| = " +
                       std::to_string(std::abs(e)) + " mm");
    const double y = std::sqrt(rho * rho - e * e);
    // The pitch point turned by σθ lands on the follower line at (e, y).
    out.theta[k] = wrap(sigma * (std::atan2(y, e) - std::atan2(p.y(), p.x())));
    out.height[k] = y;
  }
  return out;
}

}  // namespace polarform
