// The separate contours of a profile (src/fit/profile_loops): a contour with a concentric bore, or
// with a hole off the centre, or three nested loops, are that many loops with their radii; one
// contour, or one with a short second branch, is not; the message names the loops' radii.
#include "src/fit/profile_loops.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

using test::kPi;

// n points of r(θ) about `centre` at random θ in [t0, t1] with noise σ per coordinate.
Eigen::Matrix2Xd ring(const std::function<double(double)>& r, int n, Eigen::Vector2d centre,
                      double sigma, unsigned seed, double t0 = 0.0, double t1 = 2 * kPi) {
  return test::polar_points(r, n, t0, t1, centre, sigma, seed);
}

Eigen::Matrix2Xd joined(const Eigen::Matrix2Xd& a, const Eigen::Matrix2Xd& b) {
  Eigen::Matrix2Xd p(2, a.cols() + b.cols());
  p << a, b;
  return p;
}

TEST(ProfileLoops, AContourWithAConcentricBoreIsTwoLoops) {
  const Eigen::Matrix2Xd p =
      joined(ring([](double t) { return 40 + 0.5 * std::cos(3 * t); }, 3600, {0, 0}, 0.01, 1),
             ring([](double) { return 12.0; }, 400, {0, 0}, 0.01, 2));
  const std::vector<ProfileContour> c = profile_contours(p);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].points, 3600u);
  EXPECT_EQ(c[1].points, 400u);
  for (const ProfileContour& k : c) EXPECT_TRUE(k.loop && k.around_centre);
  EXPECT_NEAR(c[0].radius, 40.0, 0.03);
  EXPECT_NEAR(c[1].radius, 12.0, 0.01);
  EXPECT_EQ(describe_loops(c, {3, 4}),
            "two loops found (radii about 40 mm and 12 mm around the centre): use scan-cam, or "
            "remove the inner loop");
}

TEST(ProfileLoops, AHoleOffTheCentreIsALoopAroundItsOwnCentre) {
  const Eigen::Matrix2Xd p = joined(ring([](double) { return 40.0; }, 3000, {0, 0}, 0.01, 3),
                                    ring([](double) { return 4.0; }, 300, {20, 5}, 0.01, 4));
  const std::vector<ProfileContour> c = profile_contours(p);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_TRUE(c[1].loop);
  EXPECT_FALSE(c[1].around_centre);
  EXPECT_NEAR(c[1].centre.x(), 20.0, 0.01);
  EXPECT_NEAR(c[1].centre.y(), 5.0, 0.01);
  EXPECT_NEAR(c[1].radius, 4.0, 0.01);
  // Shown in the caller's coordinates: the polar centre there is (100, 200).
  EXPECT_EQ(describe_loops(c, {100, 200}),
            "two loops found (radius about 40 mm around the centre, radius about 4 mm around "
            "(120, 205)): use scan-cam, or remove the inner loop");
}

TEST(ProfileLoops, ThreeNestedLoops) {
  const Eigen::Matrix2Xd p =
      joined(joined(ring([](double) { return 50.0; }, 3000, {0, 0}, 0.005, 5),
                    ring([](double) { return 30.0; }, 2000, {0, 0}, 0.005, 6)),
             ring([](double) { return 10.0; }, 800, {0, 0}, 0.005, 7));
  EXPECT_EQ(describe_loops(profile_contours(p), {0, 0}),
            "three loops found (radii about 50 mm, 30 mm and 10 mm around the centre): use "
            "scan-cam, or remove the inner loops");
}

TEST(ProfileLoops, OneContourOrOneWithABranchIsNotLoops) {
  const Eigen::Matrix2Xd one =
      ring([](double t) { return 40 + 2 * std::cos(3 * t); }, 3000, {0, 0}, 0.01, 8);
  const std::vector<ProfileContour> c = profile_contours(one);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].loop);
  EXPECT_EQ(describe_loops(c, {0, 0}), "");
  // A second branch over 30°: a contour, but an open arc.
  const std::vector<ProfileContour> b = profile_contours(
      joined(one, ring([](double) { return 44.0; }, 300, {0, 0}, 0.01, 9, 1.0, 1.5)));
  ASSERT_EQ(b.size(), 2u);
  EXPECT_FALSE(b[1].loop);
  EXPECT_EQ(describe_loops(b, {0, 0}), "");
}

}  // namespace
}  // namespace polarform
