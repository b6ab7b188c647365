// Foot points on a fitted polar profile C(u) = F(u)·B(u) + centre (Bae 2002, eq. (2.1)): the
// closest point of the profile to a point near it, by Gauss–Newton from the point's synchronized
// parameter u = B.parameter(atan2) (eqs. (2.7)-(2.8)) on the factors (src/fit/product_geometry.h),
// with the unit tangent and the outward unit normal there. Local, so fast: the points must lie
// near the profile and see it single-valued from the centre (as scanned contour points do).
#pragma once

#include <Eigen/Core>

#include "src/fit/polar_curve_fit.h"
#include "src/fit/product_geometry.h"

namespace polarform {

struct ProfileFoot {
  double u = 0.0;                                    // the profile's parameter
  Eigen::Vector2d point = Eigen::Vector2d::Zero();   // C(u)
  Eigen::Vector2d normal = Eigen::Vector2d::Zero();  // outward (away from the centre), unit
  double distance = 0.0;                             // signed, positive outside
};

class ProfileFeet {
 public:
  // `fit` must outlive this object.
  explicit ProfileFeet(const PolarCurveFit& fit);
  ProfileFeet(const ProfileFeet&) = delete;
  ProfileFeet& operator=(const ProfileFeet&) = delete;

  ProfileFoot operator()(const Eigen::Vector2d& q) const;

 private:
  const PolarCurveFit& fit_;
  BSplineSurface F_;  // F as the 1 x n function ProductGeometry::polar expects
  ProductGeometry geometry_;
};

}  // namespace polarform
