// Spherical surface fitting (Bae 2002, §3.1, §3.3, §4.3): an exact sphere in arbitrary placement
// gives degree (2, 2) at round-off; a rotational freeform shape from noisy samples gives an RMS
// error at the noise level and a surface far closer to the truth than the noise; closed fits are
// seamless; G1 poles and caps collapse to one point with one tangent plane; a rigidly moved cloud
// gives the rigidly moved surface; rays that cross the data twice are refused.
#include "src/fit/spherical_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "src/error.h"
#include "src/fit/membership.h"
#include "src/nurbs/point_inversion.h"
#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

using test::kPi;

SphericalFitOptions exact(int n = 8) {
  SphericalFitOptions o;
  o.function.size_u = o.function.size_v = n;
  o.function.fairness.mode = FairnessOptions::Mode::fixed;
  o.function.fairness.weight = 0.0;
  return o;
}

// A rotational freeform shape: a sphere of radius 30 with three lobes, smooth at the poles with
// horizontal tangent planes there (sin³φ·cos 3θ is a cubic in x, y near the pole).
double lobed(double phi, double theta) {
  return 30.0 * (1.0 + 0.1 * std::pow(std::sin(phi), 3) * std::cos(3 * theta) + 0.05 * std::cos(2 * phi));
}

// The angle between two directions, accurate near 0.
double angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), std::abs(a.dot(b)));
}

TEST(SphericalFit, ExactSphereInArbitraryPlacementIsDegreeTwoTwo) {
  const test::Rigid m = test::random_rigid(1);
  const Eigen::Matrix3Xd p = m(test::spherical_cloud([](double, double) { return 40.0; }, 20000, 0, kPi, 0, 2 * kPi, 2));
  const SphericalFit f = fit_spherical(p, exact());
  ASSERT_TRUE(f.frame.quadric);
  RecordProperty("max_error", test::sci(f.report.error.max));
  RecordProperty("seam_gap", test::sci(f.seam.gap));
  EXPECT_EQ(f.frame.quadric->classification.type, QuadricType::real_ellipsoid);
  EXPECT_LT((f.frame.frame.origin - m.t).norm(), 1e-9);
  EXPECT_TRUE(f.closed);
  EXPECT_EQ(f.F.degree_u(), 0);
  EXPECT_EQ(f.F.degree_v(), 0);
  EXPECT_EQ(f.surface.degree_u(), 2);
  EXPECT_EQ(f.surface.degree_v(), 2);
  EXPECT_LT(f.report.error.max, 1e-9);
  EXPECT_LT(f.seam.gap, 1e-11);
  for (double u = f.surface.front_u(); u <= f.surface.back_u(); u += 0.05)
    for (double v = f.surface.front_v(); v <= f.surface.back_v(); v += 0.05)
      EXPECT_NEAR((f.surface.point(u, v) - m.t).norm(), 40.0, 1e-9);
}

TEST(SphericalFit, PartialSphereIsOpenAndExact) {
  // A sphere's quadric has three equal eigenvalues: any axis is right, so give one off the patch.
  const test::Rigid m = test::random_rigid(3);
  const Eigen::Matrix3Xd p = m(test::spherical_cloud([](double, double) { return 12.0; }, 5000, 0.3, 1.2, 0.5, 2.5, 4));
  SphericalFitOptions o = exact(6);
  o.frame.axis = m.R.col(2);
  const SphericalFit f = fit_spherical(p, o);
  EXPECT_LT((f.frame.frame.origin - m.t).norm(), 1e-9);
  EXPECT_FALSE(f.closed);
  EXPECT_NEAR(f.base.azimuth().breakpoints().back() - f.base.azimuth().breakpoints().front(), 2.0, 0.05);
  EXPECT_EQ(f.surface.degree_u(), 2);
  EXPECT_EQ(f.surface.degree_v(), 2);
  EXPECT_LT(f.report.error.max, 1e-9);
}

TEST(SphericalFit, NoisyFreeformShapeFitsToTheNoiseLevel) {
  const double sigma = 0.05;  // per coordinate, so σ along the normal too
  const test::Rigid m = test::random_rigid(5);
  const Eigen::Matrix3Xd truth = test::spherical_cloud(lobed, 60000, 0.25, kPi - 0.25, 0, 2 * kPi, 6);
  Eigen::Matrix3Xd p = m(truth);
  test::add_noise(p, sigma, 7);
  SphericalFitOptions o;
  o.function.size_u = o.function.size_v = 16;
  o.function.fairness.mode = FairnessOptions::Mode::gcv;
  o.frame.origin = m.t;  // the scanner's frame
  o.frame.axis = m.R.col(2);
  const SphericalFit f = fit_spherical(p, o);
  EXPECT_EQ(f.surface.degree_u(), 5);
  EXPECT_EQ(f.surface.degree_v(), 5);
  EXPECT_NEAR(f.report.error.rms, sigma, 0.1 * sigma);
  EXPECT_LE(f.report.error.rms, f.report.radial.rms);
  RecordProperty("rms_over_sigma", test::sci(f.report.error.rms / sigma));
  RecordProperty("lambda", test::sci(f.report.lambda));
  RecordProperty("dof", test::sci(f.report.dof));
  // The noise-free points lie much closer to the fitted surface than the noise.
  double sum2 = 0.0;
  for (int k = 0; k < truth.cols(); k += 10)
    sum2 += std::pow(classify_point(f, m(Eigen::Vector3d(truth.col(k))), 0.0).distance, 2);
  EXPECT_LT(std::sqrt(sum2 / (truth.cols() / 10)), 0.3 * sigma);
  RecordProperty("truth_rms_over_sigma", test::sci(std::sqrt(sum2 / (truth.cols() / 10)) / sigma));
}

TEST(SphericalFit, ReportedDistancesAreClosestPointDistances) {
  Eigen::Matrix3Xd p = test::spherical_cloud(lobed, 8000, 0.4, 2.5, 0.0, 2 * kPi, 8);
  test::add_noise(p, 0.2, 9);
  SphericalFitOptions o;
  o.function.size_u = o.function.size_v = 10;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  const SphericalFit f = fit_spherical(p, o);
  // Independent: minimise |S(u, v) − q| over a dense grid of the NURBS, then by pattern search.
  for (int k = 0; k < 8000; k += 401) {
    const Eigen::Vector3d q = p.col(k);
    double best = 1e300, bu = 0, bv = 0;
    for (int a = 0; a <= 200; ++a)
      for (int b = 0; b <= 400; ++b) {
        const double u = f.surface.front_u() + (f.surface.back_u() - f.surface.front_u()) * a / 200;
        const double v = f.surface.front_v() + (f.surface.back_v() - f.surface.front_v()) * b / 400;
        const double d = (f.surface.point(u, v) - q).norm();
        if (d < best) best = d, bu = u, bv = v;
      }
    for (double h = 0.01; h > 1e-13; h *= 0.5)
      for (int rep = 0; rep < 4; ++rep)
        for (auto [du, dv] : {std::pair{h, 0.0}, {-h, 0.0}, {0.0, h}, {0.0, -h}}) {
          const double u = std::clamp(bu + du, f.surface.front_u(), f.surface.back_u());
          const double v = std::clamp(bv + dv, f.surface.front_v(), f.surface.back_v());
          const double d = (f.surface.point(u, v) - q).norm();
          if (d < best) best = d, bu = u, bv = v;
        }
    EXPECT_NEAR(std::abs(f.report.signed_distance[k]), best, 1e-9) << k;
  }
  // And against the kernel's global point inversion on the NURBS itself.
  const SurfaceProjector projector(f.surface);
  for (int k = 0; k < 8000; k += 97)
    EXPECT_NEAR(std::abs(f.report.signed_distance[k]), projector.project(p.col(k)).distance, 1e-9) << k;
}

TEST(SphericalFit, RefinesTheNetUntilTheTrueErrorMeetsTheTolerance) {
  const Eigen::Matrix3Xd p = test::spherical_cloud(lobed, 20000, 0.3, 2.8, 0.0, 2 * kPi, 19);
  SphericalFitOptions o;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  o.function.tolerance = 0.01;  // mm, on the max closest-point distance
  o.function.fairness.mode = FairnessOptions::Mode::fixed;
  o.function.fairness.weight = 0.0;
  std::vector<double> seen;
  o.function.progress = [&](double x) { seen.push_back(x); };
  const SphericalFit f = fit_spherical(p, o);
  EXPECT_LE(f.report.error.max, 0.01);
  EXPECT_GT(f.report.refinements, 0);
  EXPECT_LT(f.report.size_u * f.report.size_v, 40 * 40);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);
  // An unreachable tolerance within the limits is an error that states what was reached.
  o.function.tolerance = 1e-7;
  o.function.max_size_u = o.function.max_size_v = 10;
  try {
    fit_spherical(p, o);
    FAIL() << "expected NumericalError";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("not met: reached"), std::string::npos) << e.what();
  }
}

TEST(SphericalFit, ClosedSurfaceWithG1PolesIsSeamlessAndTangentContinuous) {
  const Eigen::Matrix3Xd p = test::spherical_cloud(lobed, 30000, 0.35, kPi - 0.35, 0, 2 * kPi, 10);
  SphericalFitOptions o;
  o.function.size_u = 14;
  o.function.size_v = 16;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  o.north = o.south = PoleTreatment::g1;
  const SphericalFit f = fit_spherical(p, o);
  ASSERT_TRUE(f.north_pole && f.south_pole);
  RecordProperty("seam_gap", test::sci(f.seam.gap));
  RecordProperty("seam_normal_angle", test::sci(f.seam.normal_angle));
  RecordProperty("pole_gap", test::sci(std::max(f.north_pole->gap, f.south_pole->gap)));
  RecordProperty("pole_normal_spread", test::sci(std::max(f.north_pole->normal_spread, f.south_pole->normal_spread)));
  RecordProperty("max_error", test::sci(f.report.error.max));
  EXPECT_LT(f.seam.gap, 1e-12 * 30);
  EXPECT_LT(f.seam.normal_angle, 1e-9);
  for (const PoleReport* r : {&*f.north_pole, &*f.south_pole}) {
    EXPECT_LT(r->gap, 1e-12 * 30);          // (3.11)
    EXPECT_LT(r->normal_spread, 1e-9);      // (3.12)
    EXPECT_NEAR(std::abs(r->normal.z()), 1.0, 1e-12);  // horizontal tangent plane (D.4)
  }
  EXPECT_LT(f.report.error.max, 0.05);
}

TEST(SphericalFit, PoleCapsCloseTheHolesWithTheirOwnTangentPlanes) {
  // Tilted lobes so that the tangent plane at the pole is not horizontal.
  auto shape = [](double phi, double theta) { return lobed(phi, theta) + 1.5 * std::sin(phi) * std::cos(theta); };
  const Eigen::Matrix3Xd p = test::spherical_cloud(shape, 30000, 0.35, kPi - 0.35, 0, 2 * kPi, 11);
  SphericalFitOptions o;
  o.function.size_u = 12;
  o.function.size_v = 16;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  o.north = o.south = PoleTreatment::cap;
  const SphericalFit f = fit_spherical(p, o);
  ASSERT_TRUE(f.north_cap && f.south_cap);
  for (const char* side : {"north", "south"}) {
    const PoleCap& c = side[0] == 'n' ? *f.north_cap : *f.south_cap;
    RecordProperty(std::string(side) + "_boundary_gap", test::sci(c.boundary_gap));
    RecordProperty(std::string(side) + "_boundary_normal_angle", test::sci(c.boundary_normal_angle));
    RecordProperty(std::string(side) + "_pole_gap", test::sci(c.pole.gap));
    RecordProperty(std::string(side) + "_pole_normal_spread", test::sci(c.pole.normal_spread));
    RecordProperty(std::string(side) + "_normal_tilt_deg", test::sci(std::acos(std::abs(c.normal.z())) * 180 / kPi));
  }
  for (const PoleCap* c : {&*f.north_cap, &*f.south_cap}) {
    EXPECT_EQ(c->surface.degree_u(), 5);
    EXPECT_LT(c->boundary_gap, 1e-9);        // the cap's boundary is the surface's
    EXPECT_LT(c->pole.gap, 1e-12 * 30);      // G0 at p*
    EXPECT_LT(c->pole.normal_spread, 1e-9);  // one tangent plane at p* ...
    EXPECT_LT(angle(c->pole.normal, c->normal), 1e-9);  // ... n*
    EXPECT_LT(c->boundary_normal_angle, 0.05);
    EXPECT_GT(std::abs(c->normal.x()), 1e-3);  // not the horizontal plane of (3.14)
  }
  EXPECT_GT(f.north_cap->point.z(), 25.0);
  EXPECT_LT(f.south_cap->point.z(), -25.0);
}

// The largest angle between the normals S_u × S_v on the ring u = u_b ± δ (δ = 1e-7 of the
// u range) at 3600 values of v and their mean: as δ → 0, the spread of the tangent planes that
// meet at the pole, found without the normals (3.12) the fit measures.
double ring_normal_spread(const NurbsSurface& s, bool north) {
  const double du = 1e-7 * (s.back_u() - s.front_u());
  const double u = north ? s.front_u() + du : s.back_u() - du;
  std::vector<Eigen::Vector3d> normals;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int a = 0; a < 3600; ++a) {
    const double v = s.front_v() + (s.back_v() - s.front_v()) * a / 3600.0;
    const NurbsSurface::Points d = s.derivatives(u, v, 1);
    normals.push_back(d[2].cross(d[1]).normalized());  // index k·2 + l: S_u = [2], S_v = [1]
    mean += normals.back();
  }
  mean.normalize();
  double spread = 0.0;
  for (const Eigen::Vector3d& n : normals)
    spread = std::max(spread, std::atan2(n.cross(mean).norm(), n.dot(mean)));
  return spread;
}

// A noisy sphere-like scan (3000 points, σ = 0.02 mm) with its poles closed by the default G0
// condition (3.14a): near the pole F_u varies with θ as the noise has it, so the tangent planes
// there do not meet in one: the pole creases, by the spread the ring of normals shows too. G1
// poles (3.14) do not.
TEST(SphericalFit, AG0PoleThatCreasesIsFlaggedWithItsSpread) {
  Eigen::Matrix3Xd p = test::spherical_cloud(lobed, 3000, 0, kPi, 0, 2 * kPi, 3);
  test::add_noise(p, 0.02, 4);
  SphericalFitOptions o;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  const SphericalFit f = fit_spherical(p, o);
  ASSERT_EQ(f.north, PoleTreatment::g0);
  ASSERT_EQ(f.south, PoleTreatment::g0);
  for (bool north : {true, false}) {
    const PoleReport& pole = north ? *f.north_pole : *f.south_pole;
    const PoleCheck& check = north ? f.north_check : f.south_check;
    const double ring = ring_normal_spread(f.surface, north);
    RecordProperty(std::string(north ? "north" : "south") + "_spread_deg",
                   test::sci(pole.normal_spread * 180 / kPi));
    EXPECT_NEAR(pole.normal_spread, ring, 0.01 * ring);  // 201 samples of v against 3600
    EXPECT_GT(pole.normal_spread, 2 * kMaxPoleNormalSpread);
    EXPECT_TRUE(check.creased);
    EXPECT_FALSE(check.extrapolated);
    EXPECT_LT(check.nearest_data, 4 * kPi / 180);
  }
  o.north = o.south = PoleTreatment::g1;
  const SphericalFit g1 = fit_spherical(p, o);
  EXPECT_LT(ring_normal_spread(g1.surface, true), 1e-5);
  EXPECT_FALSE(g1.north_check.creased);
  EXPECT_FALSE(g1.south_check.creased);
}

// A pole closed (G1, or a cap) over a hole of 20° of polar angle is extrapolated: no data within
// pole_reach (10°); the same shape scanned to the poles is not, and an open pole never is.
TEST(SphericalFit, APoleClosedOverAHoleIsExtrapolated) {
  const Eigen::Matrix3Xd gap = test::spherical_cloud(lobed, 20000, 0.35, kPi, 0, 2 * kPi, 5);
  SphericalFitOptions o;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  const SphericalFit open = fit_spherical(gap, o);  // automatic: none at the north pole
  EXPECT_EQ(open.north, PoleTreatment::none);
  EXPECT_FALSE(open.north_check.extrapolated);
  EXPECT_NEAR(open.north_check.nearest_data, 0.35, 2e-3);
  for (PoleTreatment t : {PoleTreatment::g1, PoleTreatment::cap}) {
    o.north = t;
    const SphericalFit f = fit_spherical(gap, o);
    EXPECT_TRUE(f.north_check.extrapolated);
    EXPECT_GE(f.north_check.nearest_data, 0.35);
    EXPECT_NEAR(f.north_check.nearest_data, 0.35, 2e-3);
    EXPECT_FALSE(f.south_check.extrapolated);  // data within 1° of the south pole
    EXPECT_LT(f.south_check.nearest_data, kPi / 180);
  }
  o.north = o.south = PoleTreatment::g1;
  const SphericalFit full =
      fit_spherical(test::spherical_cloud(lobed, 20000, 0, kPi, 0, 2 * kPi, 6), o);
  EXPECT_FALSE(full.north_check.extrapolated);
  EXPECT_FALSE(full.south_check.extrapolated);
}

// Five gross outliers (±3 mm along their rays) of a noisy lobed body: refused with their count,
// or left out, when the fit is that of the other points.
TEST(SphericalFit, GrossOutliersAreRefusedOrLeftOut) {
  Eigen::Matrix3Xd p = test::spherical_cloud(lobed, 20005, 0, kPi, 0, 2 * kPi, 7);
  test::add_noise(p, 0.02, 8);
  for (Eigen::Index k = 20000; k < 20005; ++k)
    p.col(k) *= 1 + (k % 2 ? 3.0 : -3.0) / p.col(k).norm();
  SphericalFitOptions o;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  o.frame.reference = Eigen::Vector3d::UnitX();  // else i follows the cloud's principal direction
  o.function.size_u = o.function.size_v = 16;
  try {
    fit_spherical(p, o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("spherical fit: 5 outliers of 20005 points at > 8 σ (σ = 0.0", 0), 0u) << m;
    EXPECT_NEAR(test::number_after(m, "; largest "), 3.0, 0.1) << m;
    EXPECT_NE(m.find(" deg, theta "), std::string::npos) << m;
  }
  o.outliers = OutlierPolicy::reject;
  const SphericalFit f = fit_spherical(p, o);
  EXPECT_EQ(f.report.outliers.points,
            (std::vector<Eigen::Index>{20000, 20001, 20002, 20003, 20004}));
  EXPECT_EQ(f.report.error.count, 20000u);
  EXPECT_NEAR(f.report.error.rms, 0.02, 0.005);  // σ, and the 16 x 16 net's shortfall
  o.outliers = OutlierPolicy::refuse;
  const SphericalFit rest = fit_spherical(Eigen::Matrix3Xd(p.leftCols(20000)), o);
  EXPECT_LT((rest.F.coefs() - f.F.coefs()).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_EQ(f.report.error.rms, rest.report.error.rms);
}

TEST(SphericalFit, RigidlyMovedCloudGivesTheRigidlyMovedSurface) {
  const Eigen::Matrix3Xd p = test::spherical_cloud(
      [](double phi, double th) { return 20 + 2 * std::sin(phi) * std::cos(th) + std::cos(2 * phi) + 0.7 * std::sin(2 * th); },
      20000, 0.3, 2.6, 0.2, 5.5, 12);
  const test::Rigid m = test::random_rigid(13, 500.0);
  SphericalFitOptions o;
  o.function.size_u = o.function.size_v = 12;
  const SphericalFit a = fit_spherical(p, o), b = fit_spherical(m(p), o);
  ASSERT_EQ(a.surface.size_u(), b.surface.size_u());
  ASSERT_EQ(a.surface.size_v(), b.surface.size_v());
  EXPECT_EQ(a.surface.knots_u(), a.surface.knots_u());
  double worst = 0.0, wworst = 0.0;
  for (int i = 0; i < a.surface.size_u(); ++i)
    for (int j = 0; j < a.surface.size_v(); ++j) {
      worst = std::max(worst, (m(a.surface.control_point(i, j)) - b.surface.control_point(i, j)).norm());
      wworst = std::max(wworst, std::abs(a.surface.weight(i, j) - b.surface.weight(i, j)));
    }
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(wworst, 1e-12);
  RecordProperty("control_point_difference", test::sci(worst));
  EXPECT_NEAR(a.report.error.rms, b.report.error.rms, 1e-12);
}

TEST(SphericalFit, RefusesDataWhoseRaysCrossTwice) {
  // A sphere seen from a centre outside it.
  const Eigen::Matrix3Xd p = test::spherical_cloud([](double, double) { return 10.0; }, 20000, 0, kPi, 0, 2 * kPi, 14);
  SphericalFitOptions o;
  o.frame.origin = Eigen::Vector3d(15, 0, 0);
  o.frame.axis = Eigen::Vector3d::UnitZ();
  try {
    fit_spherical(p, o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("not single-valued"), std::string::npos) << msg;
    EXPECT_NE(msg.find("phi (deg) in ["), std::string::npos) << msg;
  }
}

// A hollow ball: an outer and a concentric inner sphere, both everywhere. The noise must be
// estimated within each shell, not from the distance between them.
TEST(SphericalFit, ConcentricShellsEverywhereAreRefused) {
  const Eigen::Matrix3Xd outer = test::spherical_cloud([](double, double) { return 40.0; }, 20000, 0, kPi, 0, 2 * kPi, 21);
  const Eigen::Matrix3Xd inner = test::spherical_cloud([](double, double) { return 30.0; }, 20000, 0, kPi, 0, 2 * kPi, 22);
  Eigen::Matrix3Xd p(3, outer.cols() + inner.cols());
  p << outer, inner;
  std::mt19937 rng(23);
  std::normal_distribution<double> N(0.0, 0.02);
  for (Eigen::Index k = 0; k < p.cols(); ++k) p.col(k) += Eigen::Vector3d(N(rng), N(rng), N(rng));
  SphericalFitOptions o;
  o.frame.origin = Eigen::Vector3d::Zero();
  o.frame.axis = Eigen::Vector3d::UnitZ();
  EXPECT_THROW(fit_spherical(p, o), InputError);
  // Each shell alone fits.
  EXPECT_NO_THROW(fit_spherical(outer, o));
}

TEST(SphericalFit, PointMembershipAgainstASphere) {
  const test::Rigid m = test::random_rigid(15);
  const Eigen::Matrix3Xd p = m(test::spherical_cloud([](double, double) { return 25.0; }, 10000, 0, kPi, 0, 2 * kPi, 16));
  const SphericalFit f = fit_spherical(p, exact());
  std::mt19937 rng(17);
  std::normal_distribution<double> N(0.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const Eigen::Vector3d d = Eigen::Vector3d(N(rng), N(rng), N(rng)).normalized();
    const double r = 25.0 * (0.5 + (k % 3) * 0.5) + (k % 3 == 1 ? 4e-7 : 0.0);  // 12.5, 25+, 37.5
    const MembershipResult res = classify_point(f, m(Eigen::Vector3d(r * d)), 1e-6);
    const Membership expect = k % 3 == 0 ? Membership::inside : k % 3 == 1 ? Membership::on : Membership::outside;
    EXPECT_EQ(res.where, expect) << k;
    EXPECT_NEAR(res.distance, r - 25.0, 1e-9);
    EXPECT_NEAR(res.radial, r - 25.0, 1e-9);
  }
  // Against an open patch, points whose rays miss it get no verdict.
  const SphericalFit patch = fit_spherical(
      test::spherical_cloud([](double, double) { return 25.0; }, 5000, 0.5, 1.5, 0.5, 1.5, 18), exact(5));
  EXPECT_EQ(classify_point(patch, Eigen::Vector3d(0, 0, 30), 1e-6).where, Membership::outside_domain);
}

}  // namespace
}  // namespace polarform
