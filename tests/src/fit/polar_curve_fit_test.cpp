// Polar curve fitting (Bae 2002, ch. 2): exact circles (closed and partial, any centre) give
// degree-2 NURBS at round-off; a freeform polar curve from noisy samples gives an RMS error at the
// noise level; distances are checked against dense sampling of the result; folds are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "src/error.h"
#include "src/fit/circle_fit.h"
#include "src/fit/polar_curve_fit.h"
#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

using test::kPi;
using test::polar_points;

// Distance from q to the curve by dense sampling and local refinement (independent of the fitter).
double dense_distance(const NurbsCurve2d& c, const Eigen::Vector2d& q) {
  const int m = 4000;
  double best = 1e300, bu = c.front();
  for (int i = 0; i <= m; ++i) {
    const double u = c.front() + (c.back() - c.front()) * i / m;
    const double d = (c.point(u) - q).norm();
    if (d < best) best = d, bu = u;
  }
  double h = (c.back() - c.front()) / m;
  for (int it = 0; it < 60; ++it, h *= 0.5)
    for (double u : {bu - h, bu + h})
      if (u >= c.front() && u <= c.back() && (c.point(u) - q).norm() < best) best = (c.point(u) - q).norm(), bu = u;
  return best;
}

PolarFitOptions exact() {
  PolarFitOptions o;
  o.function.fairness.mode = FairnessOptions::Mode::fixed;
  o.function.fairness.weight = 0.0;
  o.function.size_v = 10;
  return o;
}

TEST(CircleFit, FindsCentreOfAPartialArc) {
  const Eigen::Matrix2Xd p = polar_points([](double) { return 7.0; }, 200, 0.2, 1.4, {3, -2}, 0.0, 1);
  const CircleFit c = fit_circle(p);
  EXPECT_NEAR(c.centre.x(), 3.0, 1e-10);
  EXPECT_NEAR(c.centre.y(), -2.0, 1e-10);
  EXPECT_NEAR(c.radius, 7.0, 1e-10);
}

TEST(PolarCurveFit, ClosedCircleIsExactDegreeTwo) {
  const Eigen::Matrix2Xd p = polar_points([](double) { return 7.0; }, 500, 0.0, 2 * kPi, {3, -2}, 0.0, 2);
  const PolarCurveFit f = fit_polar_curve(p, exact());
  EXPECT_TRUE(f.closed);
  RecordProperty("max_error", test::sci(f.report.error.max));
  EXPECT_EQ(f.F.degree(), 0);
  EXPECT_EQ(f.curve.degree(), 2);  // C = R·B: no spurious elevation (DESIGN §4.1)
  EXPECT_EQ(f.curve.size(), 9);    // square-based circle
  EXPECT_LT(f.report.error.max, 1e-11);
  EXPECT_NEAR((f.centre - Eigen::Vector2d(3, -2)).norm(), 0.0, 1e-10);
  for (double u = f.curve.front(); u <= f.curve.back(); u += 0.01)
    EXPECT_NEAR((f.curve.point(u) - Eigen::Vector2d(3, -2)).norm(), 7.0, 1e-11);
}

TEST(PolarCurveFit, PartialArcAcrossThetaZeroIsExactDegreeTwo) {
  // 300° to 400° (crossing θ = 0), centre given.
  PolarFitOptions o = exact();
  o.centre = Eigen::Vector2d(-1, 4);
  const Eigen::Matrix2Xd p = polar_points([](double) { return 2.5; }, 300, 5.2, 7.0, {-1, 4}, 0.0, 3);
  const PolarCurveFit f = fit_polar_curve(p, o);
  EXPECT_FALSE(f.closed);
  EXPECT_EQ(f.curve.degree(), 2);
  EXPECT_LT(f.report.error.max, 1e-12);
  EXPECT_NEAR(f.base.breakpoints().front(), 5.2, 2e-2);  // starts after the gap, ends past 2π
  EXPECT_NEAR(f.base.breakpoints().back() - f.base.breakpoints().front(), 1.8, 2e-2);
}

TEST(PolarCurveFit, FreeformCurveFromNoisySamples) {
  auto r = [](double t) { return 10 + 2 * std::cos(3 * t) + 0.5 * std::sin(t); };
  const double sigma = 0.02;
  const Eigen::Matrix2Xd p = polar_points(r, 20000, 0.0, 2 * kPi, {1, 1}, sigma, 4);
  PolarFitOptions o;
  o.centre = Eigen::Vector2d(1, 1);
  o.function.size_v = 40;
  const PolarCurveFit f = fit_polar_curve(p, o);
  EXPECT_TRUE(f.closed);
  EXPECT_EQ(f.F.degree(), 3);
  EXPECT_EQ(f.curve.degree(), 5);  // p + 2 (2.10)
  EXPECT_NEAR(f.report.error.rms, sigma, 0.1 * sigma);
  RecordProperty("rms_over_sigma", test::sci(f.report.error.rms / sigma));
  EXPECT_LE(f.report.error.rms, f.report.radial.rms);  // closest point beats the ray
  // The reported distances are true closest-point distances (dense check on a subset).
  for (int k = 0; k < 20000; k += 997)
    EXPECT_NEAR(std::abs(f.report.signed_distance[k]), dense_distance(f.curve, p.col(k)), 1e-9);
  // And the curve is close to the truth, far inside the noise.
  double worst = 0;
  for (double t = 0; t < 2 * kPi; t += 0.01)
    worst = std::max(worst, dense_distance(f.curve, Eigen::Vector2d(1, 1) + r(t) * Eigen::Vector2d(std::cos(t), std::sin(t))));
  EXPECT_LT(worst, 0.25 * sigma);
  RecordProperty("truth_max_over_sigma", test::sci(worst / sigma));
}

TEST(PolarCurveFit, RefusesDataThatRaysCrossTwice) {
  // A circle plus a second branch at r = 14 over θ ∈ [1.0, 1.5] rad.
  Eigen::Matrix2Xd p = polar_points([](double) { return 10.0; }, 3000, 0.0, 2 * kPi, {0, 0}, 0.0, 5);
  const Eigen::Matrix2Xd extra = polar_points([](double) { return 14.0; }, 300, 1.0, 1.5, {0, 0}, 0.0, 6);
  Eigen::Matrix2Xd all(2, p.cols() + extra.cols());
  all << p, extra;
  PolarFitOptions o;
  o.centre = Eigen::Vector2d::Zero();
  try {
    fit_polar_curve(all, o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("not single-valued"), std::string::npos) << msg;
    EXPECT_NE(msg.find("theta (deg) in ["), std::string::npos) << msg;
  }
  const PolarCoordinates pc = polar_coordinates(all);
  const SingleValuedness c = check_single_valued(pc.theta, Eigen::VectorXd(), pc.r);
  ASSERT_EQ(c.folds.size(), 1u);
  EXPECT_NEAR(c.folds[0].s0, 1.0, 0.05);
  EXPECT_NEAR(c.folds[0].s1, 1.5, 0.05);
  EXPECT_NEAR(c.folds[0].separation, 4.0, 0.05);
  // The same circle alone, with a steep single-valued bump, passes.
  const Eigen::Matrix2Xd bump = polar_points([](double t) { return 10 + 3 * std::exp(-std::pow((t - 2) / 0.05, 2)); },
                                             5000, 0.0, 2 * kPi, {0, 0}, 0.0, 7);
  const PolarCoordinates pb = polar_coordinates(bump);
  EXPECT_TRUE(check_single_valued(pb.theta, Eigen::VectorXd(), pb.r).single_valued);
}

// A filled disc has one branch everywhere, but no curve r = F(θ): its radii scatter over the whole
// radius. It is refused, with the measured scatter; a ring as noisy as 2 % of its radius passes.
TEST(PolarCurveFit, RefusesAFilledRegion) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Eigen::Matrix2Xd disc(2, 3000);
  for (Eigen::Index k = 0; k < disc.cols(); ++k) {
    const double r = 10 * std::sqrt(U(rng)), t = 2 * kPi * U(rng);
    disc.col(k) << r * std::cos(t), r * std::sin(t);
  }
  PolarFitOptions o;
  o.centre = Eigen::Vector2d::Zero();
  try {
    fit_polar_curve(disc, o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("polar curve fit: the points fill a region"), std::string::npos) << msg;
  }
  const PolarCoordinates pc = polar_coordinates(disc);
  const SingleValuedness c = check_single_valued(pc.theta, Eigen::VectorXd(), pc.r);
  EXPECT_GT(c.noise, 0.25 * c.typical_radius);  // uniform in area: σ of r near 0.24 R
  EXPECT_NEAR(c.typical_radius, 10 * std::sqrt(0.5), 0.3);

  const Eigen::Matrix2Xd ring =
      polar_points([](double) { return 10.0; }, 3000, 0.0, 2 * kPi, {0, 0}, 0.2, 12);
  const PolarCurveFit fit = fit_polar_curve(ring, o);
  EXPECT_NEAR(fit.report.error.rms, 0.2, 0.03);
}

// A ring with a concentric bore: two branches over the whole circle. The noise must come from
// within each branch, not from the distance between them.
TEST(PolarCurveFit, ConcentricBranchesEverywhereAreAFold) {
  const double sigma = 0.01;
  const Eigen::Matrix2Xd outer = polar_points([](double) { return 40.0; }, 3000, 0.0, 2 * kPi, {0, 0}, sigma, 11);
  const Eigen::Matrix2Xd bore = polar_points([](double) { return 4.0; }, 3000, 0.0, 2 * kPi, {0, 0}, sigma, 12);
  Eigen::Matrix2Xd all(2, outer.cols() + bore.cols());
  all << outer, bore;
  const PolarCoordinates pc = polar_coordinates(all);
  const SingleValuedness c = check_single_valued(pc.theta, Eigen::VectorXd(), pc.r);
  EXPECT_FALSE(c.single_valued);
  EXPECT_NEAR(c.noise, sigma, 0.3 * sigma);
  ASSERT_EQ(c.folds.size(), 1u);
  EXPECT_NEAR(c.folds[0].separation, 36.0, 0.05);
  EXPECT_LT(c.folds[0].s0, 0.05);
  EXPECT_GT(c.folds[0].s1, 2 * kPi - 0.05);
  PolarFitOptions o;
  o.centre = Eigen::Vector2d::Zero();
  EXPECT_THROW(fit_polar_curve(all, o), InputError);
  // Either branch alone is single-valued, and its noise estimate is the true σ.
  const PolarCoordinates po = polar_coordinates(outer);
  const SingleValuedness one = check_single_valued(po.theta, Eigen::VectorXd(), po.r);
  EXPECT_TRUE(one.single_valued);
  EXPECT_NEAR(one.noise, sigma, 0.3 * sigma);
}

// A cam-like contour with a bore is two loops, named with their radii (not dozens of angle ranges).
TEST(PolarCurveFit, AContourWithABoreIsTwoLoops) {
  const Eigen::Matrix2Xd outer = polar_points([](double t) { return 40 + 0.5 * std::cos(3 * t); },
                                              3600, 0.0, 2 * kPi, {5, 7}, 0.005, 31);
  const Eigen::Matrix2Xd bore =
      polar_points([](double) { return 12.0; }, 400, 0.0, 2 * kPi, {5, 7}, 0.005, 32);
  Eigen::Matrix2Xd all(2, outer.cols() + bore.cols());
  all << outer, bore;
  PolarFitOptions o;
  o.centre = Eigen::Vector2d(5, 7);
  try {
    fit_polar_curve(all, o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "polar curve fit: two loops found (radii about 40 mm and 12 mm around the centre): "
              "use scan-cam, or remove the inner loop");
  }
}

// Fold regions beyond the third are counted, not listed: ten short second branches.
TEST(PolarCurveFit, ListsAtMostThreeFolds) {
  Eigen::Matrix2Xd all =
      polar_points([](double) { return 10.0; }, 6000, 0.0, 2 * kPi, {0, 0}, 0.0, 33);
  for (int b = 0; b < 10; ++b) {
    const Eigen::Matrix2Xd branch = polar_points([](double) { return 13.0; }, 100, 0.5 * b + 0.1,
                                                 0.5 * b + 0.3, {0, 0}, 0.0, 40 + b);
    all.conservativeResize(2, all.cols() + branch.cols());
    all.rightCols(branch.cols()) = branch;
  }
  PolarFitOptions o;
  o.centre = Eigen::Vector2d::Zero();
  try {
    fit_polar_curve(all, o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    std::size_t listed = 0;
    for (std::size_t at = m.find("theta (deg) in ["); at != std::string::npos;
         at = m.find("theta (deg) in [", at + 1))
      ++listed;
    EXPECT_EQ(listed, 3u) << m;
    EXPECT_NE(m.find(" … and 7 more; noise "), std::string::npos) << m;
  }
}

// r(θ) = 40 + 3 cos 3θ about the origin with radial noise σ = 0.01 at 3000 random angles, then five
// points moved radially by ±5 mm (alternately) at angles of their own: the last five columns.
Eigen::Matrix2Xd profile_with_outliers(unsigned seed, int outliers = 5) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> T(0, 2 * kPi);
  std::normal_distribution<double> N(0, 0.01);
  Eigen::Matrix2Xd p(2, 3000 + outliers);
  for (Eigen::Index k = 0; k < p.cols(); ++k) {
    const double t = T(rng);
    const double r = 40 + 3 * std::cos(3 * t) + (k < 3000 ? N(rng) : k % 2 ? 5.0 : -5.0);
    p.col(k) << r * std::cos(t), r * std::sin(t);
  }
  return p;
}

// A few gross outliers are counted, not called folds (with seed 3 they make two branches in a cell,
// with the others they would have pulled the fit): the message says how many and how far.
TEST(PolarCurveFit, AFewGrossOutliersAreCountedNotFitted) {
  PolarFitOptions o;
  o.centre = Eigen::Vector2d::Zero();
  for (unsigned seed : {1u, 2u, 3u, 4u}) {
    const Eigen::Matrix2Xd p = profile_with_outliers(seed);
    try {
      fit_polar_curve(p, o);
      FAIL() << "expected InputError, seed " << seed;
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_EQ(m.rfind("polar curve fit: 5 outliers of 3005 points at > 8 σ (σ = 0.00", 0), 0u)
          << m;
      EXPECT_NEAR(test::number_after(m, "; largest "), 5.0, 0.05) << m;
      EXPECT_NE(m.find(" deg): rerun with --reject-outliers"), std::string::npos) << m;
      EXPECT_EQ(m.find("not single-valued"), std::string::npos) << m;
    }
  }
  const SingleValuedness c =
      check_single_valued(polar_coordinates(profile_with_outliers(3)).theta, Eigen::VectorXd(),
                          polar_coordinates(profile_with_outliers(3)).r);
  EXPECT_FALSE(c.single_valued);  // seed 3: refused as not single-valued before
}

// Rejected, the outliers leave the fit that of the other points exactly; the distances of those
// points are at the noise level, the outliers' are their offsets along the normal.
TEST(PolarCurveFit, RejectedOutliersLeaveTheFitOfTheRest) {
  PolarFitOptions o;
  o.centre = Eigen::Vector2d::Zero();
  o.function.size_v = 24;
  o.outliers = OutlierPolicy::reject;
  for (unsigned seed : {1u, 3u}) {
    const Eigen::Matrix2Xd p = profile_with_outliers(seed);
    const PolarCurveFit f = fit_polar_curve(p, o);
    const OutlierReport& out = f.report.outliers;
    EXPECT_EQ(out.count, 5u);
    EXPECT_EQ(out.points, (std::vector<Eigen::Index>{3000, 3001, 3002, 3003, 3004}));
    EXPECT_NEAR(out.scale, 0.01, 0.0015);
    EXPECT_NEAR(out.largest, 5.0, 0.05);
    EXPECT_EQ(f.report.error.count, 3000u);
    EXPECT_NEAR(f.report.error.rms, 0.01, 0.001);
    RecordProperty("inlier_rms_over_sigma_" + std::to_string(seed),
                   test::sci(f.report.error.rms / 0.01));
    ASSERT_EQ(f.report.signed_distance.size(), 3005);
    EXPECT_LT(f.report.signed_distance.head(3000).cwiseAbs().maxCoeff(), 0.05);
    for (Eigen::Index k = 3000; k < 3005; ++k) {
      EXPECT_GT(std::abs(f.report.signed_distance[k]), 4.8) << k;  // 5 mm along rays, slope < 13°
      EXPECT_LT(std::abs(f.report.signed_distance[k]), 5.01) << k;
      EXPECT_EQ(f.report.signed_distance[k] > 0, k % 2 == 1) << k;
    }
    // The fit of the 3000 points alone, with every option else the same.
    PolarFitOptions plain = o;
    plain.outliers = OutlierPolicy::refuse;
    const PolarCurveFit rest = fit_polar_curve(Eigen::Matrix2Xd(p.leftCols(3000)), plain);
    EXPECT_LT((rest.F.values() - f.F.values()).cwiseAbs().maxCoeff(), 1e-9);
  }
}

// On clean data --reject-outliers rejects nothing and changes nothing.
TEST(PolarCurveFit, RejectingOnCleanDataChangesNothing) {
  const Eigen::Matrix2Xd p = profile_with_outliers(5, 0);
  PolarFitOptions o;
  o.function.size_v = 24;
  const PolarCurveFit plain = fit_polar_curve(p, o);
  o.outliers = OutlierPolicy::reject;
  const PolarCurveFit robust = fit_polar_curve(p, o);
  EXPECT_EQ(robust.report.outliers.count, 0u);
  EXPECT_EQ(robust.F.values(), plain.F.values());
  EXPECT_EQ(robust.report.signed_distance, plain.report.signed_distance);
  EXPECT_EQ(robust.report.error.rms, plain.report.error.rms);
  EXPECT_NEAR(plain.report.error.rms, 0.01, 0.001);
}

TEST(PolarCurveFit, SliceOfACylinderIsACircleInSpace) {
  Eigen::Matrix3Xd p = test::cylindrical_cloud([](double, double) { return 6.0; }, 20000, -5, 5, 0, 2 * kPi, 8);
  const test::Rigid m = test::random_rigid(9);
  p = m(p);
  const PlanarSlice s = slice_points(p, m.t, m.R.col(2), m.R.col(0), 0.2);
  EXPECT_GT(s.points.cols(), 300);
  PolarFitOptions o = exact();
  const PolarCurveFit f = fit_polar_curve(s.points, o);
  EXPECT_EQ(f.curve.degree(), 2);
  const NurbsCurve3d c = curve_in_space(f.curve, s.plane);
  for (double u = c.front(); u <= c.back(); u += 0.05) {
    const Eigen::Vector3d q = m.R.transpose() * (c.point(u) - m.t);
    EXPECT_NEAR(q.head<2>().norm(), 6.0, 1e-9);
    EXPECT_NEAR(q.z(), 0.0, 1e-9);
  }
}

}  // namespace
}  // namespace polarform
