// Outliers of scanned data (src/fit/outliers): gross outliers added to noisy profiles and surfaces
// are found exactly, with the noise as their σ; exact data of curved and steep shapes, and a short
// coherent second branch, have none; a few outliers explain a failed single-valuedness check and
// are refused with their count, or handed on to be left out.
#include "src/fit/outliers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "src/error.h"
#include "src/fit/orthogonal_coordinates.h"
#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

using test::kPi;

// r(θ) = 40 + 3 cos 3θ at n random angles with radial noise σ, then `bad` points moved radially
// by ±offset (alternating) at their own random angles: the last `bad` entries.
struct Profile {
  Eigen::VectorXd theta, r;
};
Profile noisy_profile(int n, double sigma, int bad, double offset, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> T(0.0, 2 * kPi);
  std::normal_distribution<double> N(0.0, sigma > 0 ? sigma : 1.0);
  Profile p{Eigen::VectorXd(n + bad), Eigen::VectorXd(n + bad)};
  for (int k = 0; k < n + bad; ++k) {
    const double t = T(rng);
    p.theta[k] = t;
    p.r[k] = 40 + 3 * std::cos(3 * t) + (sigma > 0 ? N(rng) : 0.0);
    if (k >= n) p.r[k] += (k % 2 ? offset : -offset);
  }
  return p;
}

TEST(Outliers, GrossOutliersOfANoisyProfileAreFoundExactly) {
  const double sigma = 0.01;
  for (unsigned seed : {1u, 2u, 3u}) {
    const Profile p = noisy_profile(3000, sigma, 5, 2.0, seed);
    const OutlierScan scan = find_outliers(p.theta, Eigen::VectorXd(), p.r, outlier_floor(p.r));
    ASSERT_EQ(scan.points.size(), 5u) << seed;
    for (int a = 0; a < 5; ++a) EXPECT_EQ(scan.points[static_cast<std::size_t>(a)], 3000 + a);
    EXPECT_NEAR(scan.scale, sigma, 0.15 * sigma);  // the noise, not the outliers
    EXPECT_NEAR(scan.threshold, kOutlierSigmas * scan.scale, 1e-15);
    for (int a = 0; a < 5; ++a) EXPECT_NEAR(std::abs(scan.deviation[3000 + a]), 2.0, 6 * sigma);
  }
  // Clean, the same profile has none.
  const Profile clean = noisy_profile(3000, sigma, 0, 0.0, 1);
  EXPECT_TRUE(find_outliers(clean.theta, Eigen::VectorXd(), clean.r, outlier_floor(clean.r))
                  .points.empty());
}

TEST(Outliers, ExactCurvedAndSteepShapesHaveNone) {
  // A narrow steep bump (3 mm over ±0.05 rad) on an exact circle: its points line up.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> T(0.0, 2 * kPi);
  Eigen::VectorXd theta(5000), r(5000);
  for (Eigen::Index k = 0; k < r.size(); ++k) {
    theta[k] = T(rng);
    r[k] = 10 + 3 * std::exp(-std::pow((theta[k] - 2) / 0.05, 2));
  }
  EXPECT_TRUE(find_outliers(theta, Eigen::VectorXd(), r, outlier_floor(r)).points.empty());
  // An exact lobed sphere over (φ, θ), poles included: the corners of the cells deviate from the
  // cells' quadratics by more than 8 of their median deviations, but not from their neighbours'.
  const Eigen::Matrix3Xd p = test::spherical_cloud(
      [](double phi, double th) {
        return 30 * (1 + 0.1 * std::pow(std::sin(phi), 3) * std::cos(3 * th));
      },
      30000, 0, kPi, 0, 2 * kPi, 10);
  const SphericalCoordinates sc = spherical_coordinates(p);
  EXPECT_TRUE(find_outliers(sc.phi, sc.theta, sc.rho, outlier_floor(sc.rho)).points.empty());
}

TEST(Outliers, AShortCoherentBranchIsNoOutliers) {
  // 40 points of a second branch 2 mm outside over 3°: a structure, left to the fold check.
  Profile p = noisy_profile(3000, 0.01, 0, 0.0, 4);
  p.theta.conservativeResize(3040);
  p.r.conservativeResize(3040);
  for (int a = 0; a < 40; ++a) {
    p.theta[3000 + a] = 1.0 + 0.05 * a / 40.0;
    p.r[3000 + a] = 42 + 3 * std::cos(3 * p.theta[3000 + a]);
  }
  EXPECT_TRUE(find_outliers(p.theta, Eigen::VectorXd(), p.r, outlier_floor(p.r)).points.empty());
}

TEST(Outliers, SettledByPolicy) {
  const Profile p = noisy_profile(3000, 0.01, 5, 2.0, 1);
  const SingleValuedness check = check_single_valued(p.theta, Eigen::VectorXd(), p.r);
  ASSERT_TRUE(check.single_valued);  // these 5 fall in different cells
  const auto place = [&](Eigen::Index k) { return "theta " + std::to_string(k); };
  const auto folds = [] { return InputError("folds"); };
  // keep: nothing looked for.
  const OutlierReport kept = settle_outliers(OutlierPolicy::keep, p.theta, Eigen::VectorXd(), p.r,
                                             check, true, "fit", place, folds, 1);
  EXPECT_EQ(kept.count, 0u);
  EXPECT_TRUE(kept.points.empty());
  // reject: the five, to leave out, with the largest deviation.
  const OutlierReport rejected = settle_outliers(OutlierPolicy::reject, p.theta, Eigen::VectorXd(),
                                                 p.r, check, true, "fit", place, folds, 1);
  EXPECT_EQ(rejected.count, 5u);
  EXPECT_EQ(rejected.points, (std::vector<Eigen::Index>{3000, 3001, 3002, 3003, 3004}));
  EXPECT_NEAR(rejected.largest, 2.0, 0.06);
  EXPECT_GE(rejected.largest_point, 3000);
  EXPECT_NEAR(rejected.threshold, 8 * rejected.scale, 1e-15);
  // refuse: the count, the threshold and the place of the largest, in one message.
  try {
    settle_outliers(OutlierPolicy::refuse, p.theta, Eigen::VectorXd(), p.r, check, true, "fit",
                    place, folds, 1);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("fit: 5 outliers of 3005 points at > 8 σ (σ = ", 0), 0u) << m;
    EXPECT_NE(m.find("; largest 2.0"), std::string::npos) << m;
    EXPECT_NE(m.find(" mm at theta " + std::to_string(rejected.largest_point) +
                     "): rerun with --reject-outliers"),
              std::string::npos)
        << m;
  }
}

TEST(Outliers, AFewOutliersExplainAFailedCheck) {
  // Five outliers 2 to 3.2 mm off, alternately out and in, within 2° (one or two cells): three
  // interleaved with the points outside make two branches there.
  Profile p = noisy_profile(3000, 0.01, 0, 0.0, 5);
  p.theta.conservativeResize(3005);
  p.r.conservativeResize(3005);
  for (int a = 0; a < 5; ++a) {
    p.theta[3000 + a] = 2.0 + 0.007 * a * (a % 2 ? 1 : -1);
    p.r[3000 + a] = 40 + 3 * std::cos(3 * p.theta[3000 + a]) + (a % 2 ? -1 : 1) * (2.0 + 0.3 * a);
  }
  const SingleValuedness check = check_single_valued(p.theta, Eigen::VectorXd(), p.r);
  ASSERT_FALSE(check.single_valued);
  const auto place = [](Eigen::Index) { return std::string("there"); };
  const auto folds = [] { return InputError("folds"); };
  EXPECT_EQ(settle_outliers(OutlierPolicy::reject, p.theta, Eigen::VectorXd(), p.r, check, true,
                            "fit", place, folds, 1)
                .points,
            (std::vector<Eigen::Index>{3000, 3001, 3002, 3003, 3004}));
  // keep looks for none: the folds stand.
  try {
    settle_outliers(OutlierPolicy::keep, p.theta, Eigen::VectorXd(), p.r, check, true, "fit", place,
                    folds, 1);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "folds");
  }
}

}  // namespace
}  // namespace polarform
