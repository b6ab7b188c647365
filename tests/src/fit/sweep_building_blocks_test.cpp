// Kantz 2003 building blocks: the PCA object frame of a box grid (K9 acceptance 1–2), MLS thinning
// of a circle band (K5 acceptance 1–2) and ordering of two concentric thinned circles into two
// loops (K6 acceptance 2).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "src/fit/mls_thinning.h"
#include "src/fit/point_ordering.h"
#include "src/fit/principal_frame.h"

namespace polarform {
namespace {

TEST(PrincipalFrame, BoxGridAxesCentreAndExtents) {
  Eigen::Matrix3Xd P(3, 31 * 21 * 11);
  int k = 0;
  for (int i = 0; i < 31; ++i)
    for (int j = 0; j < 21; ++j)
      for (int l = 0; l < 11; ++l) P.col(k++) << i - 15.0, j - 10.0, l - 5.0;
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d t(5, -3, 12);
  const Eigen::Matrix3Xd Q = (R * P).colwise() + t;
  const PrincipalFrame f = principal_frame(Q);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(std::abs(f.axes.col(a).dot(R.col(a))), 1.0, 1e-12);
  EXPECT_LE((f.box_centre - t).norm(), 1e-12);
  const Eigen::Vector3d extent = f.box_high - f.box_low;
  EXPECT_NEAR(extent[0], 30, 1e-12);
  EXPECT_NEAR(extent[1], 20, 1e-12);
  EXPECT_NEAR(extent[2], 10, 1e-12);
  EXPECT_EQ(f.axis_index(FrameAxis::most_distinct), 0);  // λ: 80, 36.7, 10
}

Eigen::Matrix2Xd circle_band(int n, double r, double half_width, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  Eigen::Matrix2Xd P(2, n);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * u(rng), rr = r + half_width * (2 * u(rng) - 1);
    P.col(i) << rr * std::cos(t), rr * std::sin(t);
  }
  return P;
}

TEST(MlsThinning, CircleBandBecomesThinAndUnbiased) {
  std::mt19937 rng(3);
  const Eigen::Matrix2Xd P = circle_band(20000, 10.0, 0.5, rng);
  MlsOptions o;
  o.radius = 1.0;
  const MlsThinning t = mls_thin(P, o);
  double ss = 0, mean = 0;
  for (int i = 0; i < t.points.cols(); ++i) {
    const double d = t.points.col(i).norm() - 10.0;
    ss += d * d;
    mean += d;
  }
  EXPECT_LE(std::sqrt(ss / P.cols()), 0.05);
  EXPECT_LE(std::abs(mean / P.cols()), 0.01);
  // Rotation invariance: rotating the band rotates the result.
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(37 * std::numbers::pi / 180).toRotationMatrix();
  const MlsThinning s = mls_thin(R * P, o);
  EXPECT_LE((s.points - R * t.points).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(PointOrdering, TwoConcentricCirclesAreTwoLoops) {
  std::mt19937 rng(5);
  Eigen::Matrix2Xd P(2, 4000);
  P << circle_band(2000, 10.0, 0.02, rng), circle_band(2000, 12.0, 0.02, rng);
  const std::vector<OrderedChain> chains = order_points(P, 0.5);
  ASSERT_EQ(chains.size(), 2u);
  for (const OrderedChain& c : chains) {
    EXPECT_TRUE(c.closed);
    const double r0 = P.col(c.points.front()).norm();
    int inversions = 0;
    for (int i : c.points) {
      EXPECT_NEAR(P.col(i).norm(), r0, 0.2);
    }
    // Consecutive nodes are about r apart, never across the gap to the other circle.
    for (std::size_t k = 1; k < c.nodes.size(); ++k) {
      const double d = (P.col(c.nodes[k]) - P.col(c.nodes[k - 1])).norm();
      EXPECT_LE(d, 0.55);
      if (d < 0.2) ++inversions;
    }
    EXPECT_LE(inversions, 2);
  }
}

}  // namespace
}  // namespace polarform
