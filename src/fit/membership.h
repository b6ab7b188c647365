// Point-membership classification against a fitted spherical or cylindrical surface through its
// single-valued function (Bae 2002, ch. 1 and ch. 6): the point goes into the local frame and its
// orthogonal coordinates, and its range ρ (or r) is compared with F at the synchronized parameters.
// "On" means within a tolerance of the TRUE (closest-point) distance.
#pragma once

#include <Eigen/Core>

#include "src/fit/cylindrical_fit.h"
#include "src/fit/spherical_fit.h"

namespace polarform {

enum class Membership {
  inside,          // ρ < F (nearer the centre / axis than the surface), farther than tol from it
  on,              // within tol of the surface
  outside,         // ρ > F, farther than tol
  outside_domain,  // its ray misses the fitted angle/height range: no verdict from this surface
};

struct MembershipResult {
  Membership where = Membership::outside_domain;
  double radial = 0.0;    // ρ − F(u, v) along the ray (0 outside the domain)
  double distance = 0.0;  // signed closest-point distance, positive outside (0 outside the domain)
};

// tolerance >= 0 (units of the data).
MembershipResult classify_point(const SphericalFit& fit, const Eigen::Vector3d& point, double tolerance);
MembershipResult classify_point(const CylindricalFit& fit, const Eigen::Vector3d& point, double tolerance);

}  // namespace polarform
