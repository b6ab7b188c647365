// The parts of the scanned-cam pipeline on exact data: plane fit and 2D/3D decision, bore split,
// phase alignment of periodic radius functions, and the follower-geometry helpers.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "designers/scan/cam_scan_profile.h"
#include "designers/scan/cloud_plane.h"
#include "designers/scan/phase_alignment.h"
#include "designers/scan/scanned_cam.h"
#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(CloudPlane, TiltedPlanarCloudIsPlanarWithItsNormal) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> U(-50, 50);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  Eigen::Matrix3Xd p(3, 500);
  for (Eigen::Index k = 0; k < p.cols(); ++k)
    p.col(k) = R * Eigen::Vector3d(U(rng), U(rng), 0) + Eigen::Vector3d(1, 2, 3);
  const CloudPlane plane = fit_plane(p);
  EXPECT_TRUE(plane.planar());
  EXPECT_FALSE(plane.snapped);
  EXPECT_NEAR(std::abs(plane.frame.axes.col(2).dot(R.col(2))), 1.0, 1e-12);
  EXPECT_LT(plane.max_distance, 1e-12);
  EXPECT_NEAR(plane.frame.axes.determinant(), 1.0, 1e-12);
}

TEST(CloudPlane, ZPlaneKeepsTheInputAxes) {
  Eigen::Matrix3Xd p(3, 4);
  p << 0, 10, 0, 10, 0, 0, 10, 10, 5, 5, 5, 5;
  const CloudPlane plane = fit_plane(p);
  EXPECT_TRUE(plane.snapped);
  EXPECT_TRUE(plane.frame.axes.isIdentity(0.0));
  EXPECT_EQ(plane.frame.origin.z(), 5.0);
  EXPECT_THROW(fit_plane(p, Eigen::Vector3d::Zero()), InputError);
}

TEST(SplitBore, SeparatesTheInnerCircle) {
  Eigen::Matrix2Xd q(2, 300);
  for (int k = 0; k < 300; ++k) {
    const double a = 2 * kPi * k / 100;
    q.col(k) =
        (k < 100 ? 6.0 : 30.0 + 5 * std::cos(3 * a)) * Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  Eigen::Matrix2Xd inner, outer;
  split_bore(q, Eigen::Vector2d(0.3, -0.2), inner, outer);
  EXPECT_EQ(inner.cols(), 100);
  EXPECT_EQ(outer.cols(), 200);
  split_bore(q.rightCols(200), Eigen::Vector2d::Zero(), inner, outer);  // no bore
  EXPECT_EQ(inner.cols(), 0);
  EXPECT_EQ(outer.cols(), 200);
}

TEST(PhaseAlignment, FindsShiftAndMirrorOfAPeriodicRadius) {
  const auto nominal = [](double t) {
    return 40 + 5 * std::cos(t) + 2 * std::sin(2 * t) + std::cos(3 * t);
  };
  const double delta = 1.234567;
  const PhaseAlignment a =
      align_phase([&](double psi) { return nominal(psi - delta); }, nominal, true);
  EXPECT_FALSE(a.mirrored);
  EXPECT_NEAR(a.phase, delta, 1e-8);
  EXPECT_LT(a.rms, 1e-7);
  const PhaseAlignment m =
      align_phase([&](double psi) { return nominal(-psi - delta); }, nominal, true);
  EXPECT_TRUE(m.mirrored);
  EXPECT_NEAR(m.phase, delta, 1e-8);
  EXPECT_THROW(align_phase(nominal, nominal, false, 8), InputError);
}

TEST(RestHeight, InvertsTheFollowerGeometry) {
  for (const Follower f :
       {Follower{FollowerKind::KnifeEdge, 5.0, 0.0}, Follower{FollowerKind::Roller, -7.0, 12.0},
        Follower{FollowerKind::FlatFaced, 0.0, 0.0}}) {
    const double y0 = rest_height(f, 40.0);
    EXPECT_NEAR(base_radius_from_rest(f, y0), 40.0, 1e-12);
  }
  EXPECT_NEAR(rest_height(Follower{FollowerKind::Roller, 0.0, 10.0}, 40.0), 50.0, 1e-12);
}

}  // namespace
}  // namespace polarform
