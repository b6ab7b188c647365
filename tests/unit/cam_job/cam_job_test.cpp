// The cam job in memory: for every example the exported curve meets the tolerance under an
// independent dense sampling (and the job's measured error is the true maximum), the degree is the
// product degree, the curve is closed; the roller and flat-faced analyses equal textbook closed
// forms; tolerances below kMinTolerance are refused as bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cam_job_support.h"
#include "closed_forms.h"
#include "src/error.h"

namespace polarform {
namespace {

using namespace cam_job_test;

// ψ moved into [start, start + 2π).
double into_domain(double psi, double start) {
  while (psi < start) psi += 2 * kPi;
  while (psi >= start + 2 * kPi) psi -= 2 * kPi;
  return psi;
}

// Max |radius − R(ψ)| of a plate profile, or max |z − height(φ)| of a cylindrical track (whose
// points must also lie on the pitch cylinder), at `count` equally spaced curve parameters.
double sampled_error(const CamJobResult& r, int count) {
  const PolarFunction& R = r.profile_function;
  double worst = 0;
  for (int k = 0; k <= count; ++k) {
    if (r.plate) {
      const double u = r.profile.front() + (r.profile.back() - r.profile.front()) * k / count;
      const Eigen::Vector2d p = r.profile(u);
      const double psi = into_domain(std::atan2(p.y(), p.x()), R.start);
      worst = std::max(worst, std::abs(p.norm() - R(psi)));
    } else {
      const double u = r.track.front() + (r.track.back() - r.track.front()) * k / count;
      const Eigen::Vector3d p = r.track(u);
      EXPECT_NEAR(p.head<2>().norm(), r.project.cam.cylinder_radius, 1e-9) << "u = " << u;
      const double phi = into_domain(std::atan2(p.y(), p.x()), R.start);
      worst = std::max(worst, std::abs(p.z() + r.track_offset - R(phi)));
    }
  }
  return worst;
}

TEST(CamJob, EveryExampleMeetsItsToleranceUnderIndependentSampling) {
  for (const std::string& name : kExampleNames) {
    const CamJobResult& r = example(name).result;
    const PolarConversion& c = r.conversion;
    const double measured = sampled_error(r, 40000);
    EXPECT_LE(measured, r.project.conversion.tolerance) << name;
    // The job's own figure is the maximum: dense sampling finds no more, and nearly as much.
    EXPECT_LE(measured, c.max_radial_error * (1 + 1e-9) + 1e-13) << name;
    EXPECT_GE(measured, 0.9 * c.max_radial_error) << name;
    EXPECT_LE(c.max_radial_error, c.tolerance) << name;
    EXPECT_LE(c.max_normal_error, c.max_radial_error + 1e-13) << name;
  }
}

TEST(CamJob, ProfileHasTheProductDegreeAndIsClosed) {
  for (const std::string& name : kExampleNames) {
    const CamJobResult& r = example(name).result;
    const int degree = r.conversion.function.spline().degree() + 4;  // quartic base: deg F + 4
    if (r.plate) {
      EXPECT_EQ(r.profile.degree(), degree) << name;
      EXPECT_LT((r.profile(r.profile.front()) - r.profile(r.profile.back())).norm(), 1e-12) << name;
      ASSERT_TRUE(r.limited) << name;
      EXPECT_EQ(r.limited->curve.degree(), 3) << name;
      EXPECT_LE(r.limited->max_radial_error, r.project.conversion.tolerance) << name;
    } else {
      EXPECT_EQ(r.track.degree(), degree) << name;
      EXPECT_LT((r.track(r.track.front()) - r.track(r.track.back())).norm(), 1e-12) << name;
      EXPECT_FALSE(r.limited) << name;
    }
  }
}

TEST(CamJob, RollerAnalysesEqualTheClosedForms) {
  const CamJobResult& r = example("roller").result;
  ASSERT_TRUE(r.analysis);
  const double prime = 50;  // base radius 40 + roller radius 10
  double pressure = 0, pitch_radius = INFINITY;
  for (int k = 0; k < 360000; ++k) {
    const double theta = k * 1e-3;
    const Motion m = roller_motion(theta);
    // Radial translating roller: tan α = s' / (Rb + Rr + s).
    pressure = std::max(pressure, std::abs(std::atan(m.v / (prime + m.s))));
    const double rho = polar_radius_of_curvature(prime + m.s, m.v, m.a);
    if (rho > 0) pitch_radius = std::min(pitch_radius, rho);
  }
  EXPECT_NEAR(r.analysis->max_pressure_angle.value, pressure, 1e-9);
  EXPECT_NEAR(r.analysis->min_convex_pitch_radius.value, pitch_radius, 1e-7);
  // The contour is the pitch curve offset inwards by the roller radius.
  EXPECT_NEAR(r.analysis->min_convex_contour_radius.value, pitch_radius - 10, 1e-7);
  EXPECT_TRUE(r.analysis->undercut.empty());
}

TEST(CamJob, FlatFacedAnalysesEqualTheClosedForms) {
  const CamJobResult& r = example("flat_faced").result;
  ASSERT_TRUE(r.analysis);
  double radius = INFINITY;
  for (int k = 0; k < 360000; ++k) {
    double d[3];
    r.program.derivatives(k * 1e-3 * kRadiansPerDegree, 2, d);
    radius = std::min(radius, 35 + d[0] + d[2]);  // flat face: ρ = Rb + s + s''
  }
  EXPECT_NEAR(r.analysis->min_convex_contour_radius.value, radius, 1e-7);
  EXPECT_EQ(r.analysis->max_pressure_angle.value, 0.0);  // a radial flat face pushes along its axis
  EXPECT_TRUE(r.analysis->undercut.empty());
}

TEST(CamJob, RefusesToleranceBelowTheFloor) {
  CamProject p = load_example("roller");
  p.conversion.tolerance = 1e-12;
  try {
    run_cam_job(p);
    FAIL() << "no error for a 1e-12 mm tolerance";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1e-12"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1e-09"), std::string::npos) << e.what();
  }
}

// The degree-3 extra cannot follow the harmonic return's acceleration jump down to 1e-8 mm with
// uniform knots; the exact profile can, so the job warns and goes on.
TEST(CamJob, UnreachableDegreeLimitedProfileIsAWarningNotAFailure) {
  EXPECT_TRUE(example("roller").result.warnings.empty());
  CamProject p = load_example("offset_roller");
  p.conversion.tolerance = 1e-8;
  const CamJobResult r = run_cam_job(p);
  EXPECT_FALSE(r.limited.has_value());
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_NE(r.warnings[0].find("degree-3 profile not written"), std::string::npos) << r.warnings[0];
  EXPECT_NE(r.warnings[0].find("1e-08 mm"), std::string::npos) << r.warnings[0];
  EXPECT_LE(r.conversion.max_radial_error, 1e-8);
}

}  // namespace
}  // namespace polarform
