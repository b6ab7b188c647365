#include "jobs/fit/profile_interrogation.h"

#include <cmath>

#include "src/nurbs/curve_interrogation.h"
#include "src/units.h"

namespace polarform {

namespace {

// The polar angle of the curve point at u about the fit's centre, in [0°, 360°).
double angle_at(const PolarCurveFit& fit, double u) {
  const Eigen::Vector2d d = fit.curve.point(u) - fit.centre;
  const double a = std::atan2(d.y(), d.x()) * kDegreesPerRadian;
  return a < 0 ? a + 360 : a;
}

}  // namespace

ProfileInterrogation interrogate_profile(const ProfileFit& fit, int samples) {
  const NurbsCurve2d& c = fit.polar.curve;
  ProfileInterrogation out;
  out.order = c.degree();
  for (int i = 0; i <= samples; ++i) {
    const double u = c.front() + (c.back() - c.front()) * i / samples;
    out.angle_deg.push_back(angle_at(fit.polar, u));
    out.curvature.push_back(signed_curvature(c, u));
  }
  for (const double u : inflections(c)) out.inflections.push_back({u, angle_at(fit.polar, u), 0.0});
  for (const KnotJump& j : derivative_jumps(c, c.degree()))
    out.derivative_jumps.push_back({j.u, angle_at(fit.polar, j.u), j.jump});
  return out;
}

}  // namespace polarform
