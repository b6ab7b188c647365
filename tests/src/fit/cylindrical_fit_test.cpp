// Cylindrical surface fitting (Bae 2002, §3.2, §3.3.1, §4.3): exact cylinders give degree (1, 2)
// and exact surfaces of revolution (3, 2) at round-off in any placement; closed freeform fits are
// seamless; points are classified inside / on / outside; the automatic method choice follows the
// quadric and the achieved error.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "src/error.h"
#include "src/fit/membership.h"
#include "src/fit/rotational_fit.h"
#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

using test::kPi;

CylindricalFitOptions exact(int nu = 6, int nv = 8) {
  CylindricalFitOptions o;
  o.function.size_u = nu;
  o.function.size_v = nv;
  o.function.fairness.mode = FairnessOptions::Mode::fixed;
  o.function.fairness.weight = 0.0;
  return o;
}

// Angle between two lines.
double line_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), std::abs(a.dot(b)));
}

TEST(CylindricalFit, ExactCylinderIsDegreeOneTwo) {
  const test::Rigid m = test::random_rigid(21);
  const Eigen::Matrix3Xd p = m(test::cylindrical_cloud([](double, double) { return 20.0; }, 20000, -25, 25, 0, 2 * kPi, 22));
  const CylindricalFit f = fit_cylindrical(p, exact());
  ASSERT_TRUE(f.frame.quadric);
  RecordProperty("max_error", test::sci(f.report.error.max));
  EXPECT_EQ(f.frame.quadric->classification.type, QuadricType::real_elliptic_cylinder);
  EXPECT_LT(line_angle(f.frame.frame.axes.col(2), m.R.col(2)), 1e-10);
  EXPECT_TRUE(f.closed);
  EXPECT_EQ(f.F.degree_u(), 0);
  EXPECT_EQ(f.F.degree_v(), 0);
  EXPECT_EQ(f.surface.degree_u(), 1);
  EXPECT_EQ(f.surface.degree_v(), 2);
  EXPECT_LT(f.report.error.max, 1e-9);
  for (double u = 0; u <= 1; u += 0.1)
    for (double v = f.surface.front_v(); v <= f.surface.back_v(); v += 0.05) {
      const Eigen::Vector3d q = m.R.transpose() * (f.surface.point(u, v) - m.t);
      EXPECT_NEAR(q.head<2>().norm(), 20.0, 1e-9);
    }
}

TEST(CylindricalFit, ExactSurfaceOfRevolutionIsDegreeThreeTwo) {
  // A vase: r(z) a cubic in z. The best-fit quadric of a cloud has the cloud's symmetry, so the
  // estimated axis is exact when the sampling is symmetric (here: 48 equal azimuths); for a
  // random sample of a non-quadric shape it is only as good as the sample (see FrameEstimation).
  auto r = [](double z) { const double s = z / 60; return 14 + 9 * s - 12 * s * s + 4 * s * s * s; };
  const test::Rigid m = test::random_rigid(23);
  const Eigen::Matrix3Xd p = m(test::revolution_grid(r, 48, 600, 0, 60, 24));
  const CylindricalFit f = fit_cylindrical(p, exact(8, 8));
  RecordProperty("max_error", test::sci(f.report.error.max));
  EXPECT_LT(line_angle(f.frame.frame.axes.col(2), m.R.col(2)), 1e-9);
  EXPECT_EQ(f.F.degree_u(), 3);
  EXPECT_EQ(f.F.degree_v(), 0);
  EXPECT_EQ(f.surface.degree_u(), 3);
  EXPECT_EQ(f.surface.degree_v(), 2);
  EXPECT_LT(f.report.error.max, 1e-9);
}

TEST(CylindricalFit, PartialSurfaceOfRevolutionIsExactAndOpen) {
  auto r = [](double z, double) { return 10 + 0.02 * z * z; };  // a paraboloid-like bowl wall
  const test::Rigid m = test::random_rigid(25);
  const Eigen::Matrix3Xd p = m(test::cylindrical_cloud(r, 10000, 5, 20, 1.0, 3.5, 26));
  CylindricalFitOptions o = exact(5, 6);
  o.frame.origin = m.t;
  o.frame.axis = m.R.col(2);
  const CylindricalFit f = fit_cylindrical(p, o);
  EXPECT_FALSE(f.closed);
  EXPECT_EQ(f.F.degree_v(), 0);
  EXPECT_EQ(f.surface.degree_u(), 3);  // max(p, 1): F is a cubic B-spline (its cubic term zero)
  EXPECT_EQ(f.surface.degree_v(), 2);
  EXPECT_LT(f.report.error.max, 1e-9);
}

TEST(CylindricalFit, ClosedFreeformIsSeamless) {
  auto r = [](double z, double t) { return 15 + 2 * std::cos(2 * t) * std::sin(z / 10) + 0.5 * std::sin(t); };
  Eigen::Matrix3Xd p = test::cylindrical_cloud(r, 40000, -20, 20, 0, 2 * kPi, 27);
  test::add_noise(p, 0.02, 28);
  CylindricalFitOptions o;
  o.function.size_u = 10;
  o.function.size_v = 20;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  const CylindricalFit f = fit_cylindrical(p, o);
  EXPECT_TRUE(f.closed);
  EXPECT_EQ(f.surface.degree_u(), 3);
  EXPECT_EQ(f.surface.degree_v(), 5);
  EXPECT_LT(f.seam.gap, 1e-12 * 15);
  EXPECT_LT(f.seam.normal_angle, 1e-9);
  EXPECT_NEAR(f.report.error.rms, 0.02, 0.002);
  RecordProperty("seam_gap", test::sci(f.seam.gap));
  RecordProperty("seam_normal_angle", test::sci(f.seam.normal_angle));
  RecordProperty("rms", test::sci(f.report.error.rms));
}

TEST(CylindricalFit, PointMembershipAgainstASurfaceOfRevolution) {
  auto r = [](double z, double) { return 10 + 0.1 * z; };
  const test::Rigid m = test::random_rigid(29);
  const Eigen::Matrix3Xd p = m(test::cylindrical_cloud(r, 10000, 0, 30, 0, 2 * kPi, 30));
  CylindricalFitOptions o = exact(4, 6);
  o.frame.origin = m.t;
  o.frame.axis = m.R.col(2);
  const CylindricalFit f = fit_cylindrical(p, o);
  const double slope = 0.1, cosa = 1 / std::sqrt(1 + slope * slope);
  for (int k = 0; k < 90; ++k) {
    const double z = 1 + k * 0.3, t = k * 0.7, rr = r(z, t) + (k % 3 - 1) * 0.5;
    const Eigen::Vector3d q = m(Eigen::Vector3d(rr * std::cos(t), rr * std::sin(t), z));
    const MembershipResult res = classify_point(f, q, 1e-6);
    EXPECT_EQ(res.where, k % 3 == 0 ? Membership::inside : k % 3 == 1 ? Membership::on : Membership::outside);
    EXPECT_NEAR(res.radial, (k % 3 - 1) * 0.5, 1e-9);
    EXPECT_NEAR(res.distance, (k % 3 - 1) * 0.5 * cosa, 1e-9);  // normal distance to a cone
  }
  EXPECT_EQ(classify_point(f, m(Eigen::Vector3d(5, 0, 40)), 1e-6).where, Membership::outside_domain);
}

TEST(RotationalFit, ChoosesTheMethodFromTheQuadricAndTheError) {
  const test::Rigid m = test::random_rigid(31);
  RotationalFitOptions o;
  o.spherical.function.size_u = o.spherical.function.size_v = 8;
  o.cylindrical.function.size_u = o.cylindrical.function.size_v = 8;
  // A flattened sphere-like shape: an ellipsoid, fitted spherically.
  const RotationalFit a = fit_rotational(m(test::spherical_cloud(
      [](double phi, double) { return 20 / std::sqrt(1 + 0.3 * std::cos(phi) * std::cos(phi)); }, 20000, 0, kPi, 0, 2 * kPi, 32)), o);
  EXPECT_EQ(a.method(), FitMethod::spherical);
  EXPECT_NE(a.reason.find("real ellipsoid"), std::string::npos) << a.reason;
  EXPECT_LT(a.report().error.max, 2e-2);  // an 8 x 8 bicubic F: within 0.1% of the size
  // A waisted, open-ended tube: a hyperboloid of one sheet, fitted cylindrically.
  const RotationalFit b = fit_rotational(m(test::cylindrical_cloud(
      [](double z, double) { return std::sqrt(100 + 0.5 * z * z); }, 20000, -20, 20, 0, 2 * kPi, 33)), o);
  EXPECT_EQ(b.method(), FitMethod::cylindrical);
  EXPECT_NE(b.reason.find("hyperboloid of one sheet"), std::string::npos) << b.reason;
  EXPECT_LT(b.report().error.max, 2e-2);
  // Forced.
  o.method = FitMethod::cylindrical;
  const RotationalFit c = fit_rotational(m(test::cylindrical_cloud([](double, double) { return 9.0; }, 5000, 0, 30, 0, 2 * kPi, 34)), o);
  EXPECT_EQ(c.method(), FitMethod::cylindrical);
  EXPECT_EQ(c.surface().degree_u(), 1);
}

// Five gross outliers (±2 mm off the axis) of an exact waisted surface: refused with their count
// and place (z, θ), or left out, when the fit is exactly that of the other points.
TEST(CylindricalFit, GrossOutliersAreRefusedOrLeftOut) {
  Eigen::Matrix3Xd p = test::cylindrical_cloud(
      [](double z, double t) { return 20 + 2 * std::sin(z / 10) + std::cos(2 * t); }, 10005, 0, 60,
      0, 2 * kPi, 35);
  for (Eigen::Index k = 10000; k < 10005; ++k)
    p.col(k).head<2>() *= 1 + (k % 2 ? 2.0 : -2.0) / p.col(k).head<2>().norm();
  CylindricalFitOptions o;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  o.frame.reference = Eigen::Vector3d::UnitX();  // else i follows the cloud's principal direction
  try {
    fit_cylindrical(p, o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("cylindrical fit: 5 outliers of 10005 points at > 8 σ (σ = ", 0), 0u) << m;
    EXPECT_NEAR(test::number_after(m, "; largest "), 2.0, 0.01) << m;
    EXPECT_NE(m.find(" mm at z "), std::string::npos) << m;
  }
  o.outliers = OutlierPolicy::reject;
  const CylindricalFit f = fit_cylindrical(p, o);
  EXPECT_EQ(f.report.outliers.points,
            (std::vector<Eigen::Index>{10000, 10001, 10002, 10003, 10004}));
  EXPECT_EQ(f.report.error.count, 10000u);
  for (Eigen::Index k = 10000; k < 10005; ++k)
    EXPECT_NEAR(std::abs(f.report.signed_distance[k]), 2.0, 0.1);
  o.outliers = OutlierPolicy::refuse;
  const CylindricalFit rest = fit_cylindrical(Eigen::Matrix3Xd(p.leftCols(10000)), o);
  EXPECT_LT((rest.F.coefs() - f.F.coefs()).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_EQ(f.report.error.max, rest.report.error.max);
}

// A tube: an outer and a concentric inner wall, both everywhere — refused as not single-valued.
TEST(CylindricalFit, ConcentricWallsEverywhereAreRefused) {
  const Eigen::Matrix3Xd outer = test::cylindrical_cloud([](double, double) { return 25.0; }, 20000, -30, 30, 0, 2 * kPi, 31);
  const Eigen::Matrix3Xd inner = test::cylindrical_cloud([](double, double) { return 20.0; }, 20000, -30, 30, 0, 2 * kPi, 32);
  Eigen::Matrix3Xd p(3, outer.cols() + inner.cols());
  p << outer, inner;
  std::mt19937 rng(33);
  std::normal_distribution<double> N(0.0, 0.02);
  for (Eigen::Index k = 0; k < p.cols(); ++k) p.col(k) += Eigen::Vector3d(N(rng), N(rng), N(rng));
  CylindricalFitOptions o;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  EXPECT_THROW(fit_cylindrical(p, o), InputError);
  EXPECT_NO_THROW(fit_cylindrical(outer, o));
}

}  // namespace
}  // namespace polarform
