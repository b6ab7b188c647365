// Exact shapes from noisy data (issue 19): the F distribution's tail against closed forms; a
// surface of revolution r = 10 + 3 sin(z/5) sampled at random θ comes back as the exact degree
// (3, 2) surface of revolution at σ = 0, 0.001, 0.01 within max(σ, 1e-4) of the truth; a real θ
// variation of 0.05 mm at σ = 0.005 is kept; noisy spheres are exact spheres (2, 2) and noisy
// circles exact circles (degree 2); a triaxial ellipsoid is not made rotational.
#include <gtest/gtest.h>

#include <cmath>

#include "src/fit/cylindrical_fit.h"
#include "src/fit/f_distribution.h"
#include "src/fit/polar_curve_fit.h"
#include "src/fit/spherical_fit.h"
#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

using test::kPi;

TEST(FDistribution, TailMatchesClosedForms) {
  // d1 = 2: P(F > f) = (1 + 2f/d2)^(−d2/2); d1 = d2 = 1: 1 − (2/π) atan √f.
  for (double d2 : {3.0, 10.0, 1000.0, 1e6})
    for (double f : {0.1, 1.0, 3.0, 9.0})
      EXPECT_NEAR(f_upper_tail(f, 2.0, d2), std::pow(1.0 + 2.0 * f / d2, -d2 / 2.0), 1e-10)
          << d2 << " " << f;
  for (double f : {0.01, 0.5, 4.0, 100.0})
    EXPECT_NEAR(f_upper_tail(f, 1.0, 1.0), 1.0 - 2.0 / kPi * std::atan(std::sqrt(f)), 1e-10);
  // (1 + 2f/d2)^(−d2/2) = α  ⇔  f = d2/2 · (α^(−2/d2) − 1).
  EXPECT_NEAR(f_critical_value(1e-3, 2.0, 50.0), 25.0 * (std::pow(1e-3, -2.0 / 50.0) - 1.0), 1e-8);
}

double profile(double z) { return 10.0 + 3.0 * std::sin(z / 5.0); }

CylindricalFitOptions true_axis() {
  CylindricalFitOptions o;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  return o;
}

// rms over a grid of the fitted surface of its distance to r = profile(z) (radial gap times the
// profile's cosine of slope).
double truth_rms(const NurbsSurface& s) {
  double sum = 0.0;
  int n = 0;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j <= 60; ++j) {
      const double u = s.front_u() + (s.back_u() - s.front_u()) * i / 60.0;
      const double v = s.front_v() + (s.back_v() - s.front_v()) * j / 60.0;
      const Eigen::Vector3d q = s.point(u, v);
      const double slope = 0.6 * std::cos(q.z() / 5.0);
      const double d = (q.head<2>().norm() - profile(q.z())) / std::sqrt(1.0 + slope * slope);
      sum += d * d, ++n;
    }
  return std::sqrt(sum / n);
}

TEST(RevolutionTest, NoisySurfaceOfRevolutionIsExactDegreeThreeTwo) {
  for (double sigma : {0.0, 0.001, 0.01}) {
    Eigen::Matrix3Xd p = test::cylindrical_cloud([](double z, double) { return profile(z); }, 20000,
                                                 0.0, 40.0, 0.0, 2 * kPi, 41);
    if (sigma > 0) test::add_noise(p, sigma, 42);
    const CylindricalFit f = fit_cylindrical(p, true_axis());
    const double rms = truth_rms(f.surface);
    RecordProperty("truth_rms_" + test::sci(sigma), test::sci(rms));
    EXPECT_TRUE(f.report.revolution.tested);
    EXPECT_TRUE(f.report.revolution.rotational) << f.report.revolution.reason;
    EXPECT_EQ(f.surface.degree_u(), 3) << sigma;
    EXPECT_EQ(f.surface.degree_v(), 2) << sigma;
    EXPECT_LE(rms, std::max(sigma, 1e-4)) << sigma;
    if (sigma > 0) {
      EXPECT_LT(f.report.error.rms, 1.1 * sigma) << sigma;
    }
  }
}

TEST(RevolutionTest, SmallRealThetaVariationIsKept) {
  Eigen::Matrix3Xd p = test::cylindrical_cloud(
      [](double z, double t) { return profile(z) + 0.05 * std::cos(2 * t); }, 20000, 0.0, 40.0, 0.0,
      2 * kPi, 43);
  test::add_noise(p, 0.005, 44);
  const CylindricalFit f = fit_cylindrical(p, true_axis());
  EXPECT_TRUE(f.report.revolution.tested);
  EXPECT_FALSE(f.report.revolution.rotational) << f.report.revolution.reason;
  EXPECT_LT(f.report.revolution.p_value, kRevolutionAlpha);
  EXPECT_GT(f.surface.degree_v(), 2);
  EXPECT_LT(f.report.error.rms, 1.2 * 0.005);
}

TEST(RevolutionTest, AskedModesOverrideTheTest) {
  Eigen::Matrix3Xd p = test::cylindrical_cloud(
      [](double z, double t) { return profile(z) + 0.05 * std::cos(2 * t); }, 5000, 0.0, 40.0, 0.0,
      2 * kPi, 45);
  CylindricalFitOptions o = true_axis();
  o.model.revolution = RevolutionMode::yes;
  const CylindricalFit yes = fit_cylindrical(p, o);
  EXPECT_FALSE(yes.report.revolution.tested);
  EXPECT_EQ(yes.surface.degree_v(), 2);
  EXPECT_NEAR(yes.report.error.rms, 0.05 / std::sqrt(2.0), 0.005);  // the cos 2θ term, left out
  Eigen::Matrix3Xd q = test::cylindrical_cloud([](double z, double) { return profile(z); }, 5000,
                                               0.0, 40.0, 0.0, 2 * kPi, 46);
  o.model.revolution = RevolutionMode::no;
  const CylindricalFit no = fit_cylindrical(q, o);
  EXPECT_FALSE(no.report.revolution.rotational);
  EXPECT_EQ(no.surface.degree_v(), 5);
}

SphericalFit fit_about_z(const Eigen::Matrix3Xd& p) {
  SphericalFitOptions o;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  return fit_spherical(p, o);
}

TEST(RevolutionTest, NoisySphereIsAnExactSphere) {
  Eigen::Matrix3Xd p = test::spherical_cloud([](double, double) { return 25.0; }, 20000, 0.2,
                                             kPi - 0.2, 0.0, 2 * kPi, 47);
  test::add_noise(p, 0.01, 48);
  const SphericalFit f = fit_about_z(p);
  EXPECT_TRUE(f.report.revolution.rotational) << f.report.revolution.reason;
  EXPECT_EQ(f.surface.degree_v(), 2);
  for (double u = f.surface.front_u(); u <= f.surface.back_u(); u += 0.05)
    EXPECT_NEAR(f.surface.point(u, f.surface.front_v()).norm(), 25.0, 0.01);
  EXPECT_LT(f.report.error.rms, 1.1 * 0.01);
}

TEST(RevolutionTest, TriaxialEllipsoidIsNotRotational) {
  Eigen::Matrix3Xd p = test::spherical_cloud([](double, double) { return 1.0; }, 20000, 0.2,
                                             kPi - 0.2, 0.0, 2 * kPi, 49);
  p.row(0) *= 30.0, p.row(1) *= 25.0, p.row(2) *= 20.0;
  test::add_noise(p, 0.01, 50);
  const SphericalFit f = fit_about_z(p);
  EXPECT_FALSE(f.report.revolution.rotational) << f.report.revolution.reason;
  EXPECT_GT(f.surface.degree_v(), 2);
}

TEST(RevolutionTest, NoisyCircleIsAnExactCircle) {
  const Eigen::Matrix2Xd p = test::polar_points([](double) { return 15.0; }, 3000, 0.0, 2 * kPi,
                                                Eigen::Vector2d(1.0, -2.0), 0.01, 51);
  PolarFitOptions o;
  o.centre = Eigen::Vector2d(1.0, -2.0);
  const PolarCurveFit f = fit_polar_curve(p, o);
  EXPECT_TRUE(f.report.revolution.rotational) << f.report.revolution.reason;
  EXPECT_EQ(f.curve.degree(), 2);
  EXPECT_EQ(f.F.degree(), 0);
  EXPECT_NEAR(f.F(f.F.front()), 15.0, 0.002);
}

}  // namespace
}  // namespace polarform
