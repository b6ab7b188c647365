// Spine frames (MIT 13.472J §8.3; Wang et al. 2008): the rotation-minimising frame along a helix
// against its closed form (it turns against the Frenet frame by −τ·s, spec M6-2), Frenet frames
// of a rational circle, the fixed frame of a planar spine, and the refusals.
#include "src/nurbs/sweep_frames.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "src/error.h"
#include "tests/src/nurbs/helix_spine.h"
#include "tests/src/nurbs/kernel_test_support.h"

namespace polarform {
namespace {

// A full circle of radius R in the plane z = 0 about (1, 2, 0) (four rational quadratic arcs).
NurbsCurve3d circle(double R) {
  const double w = std::sqrt(0.5);
  NurbsCurve3d::Points P{{R, 0, 0},   {R, R, 0},  {0, R, 0},  {-R, R, 0}, {-R, 0, 0},
                         {-R, -R, 0}, {0, -R, 0}, {R, -R, 0}, {R, 0, 0}};
  for (auto& p : P) p += Eigen::Vector3d(1, 2, 0);
  return NurbsCurve3d(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, P,
                      {1, w, 1, w, 1, w, 1, w, 1});
}

void expect_orthonormal(const SpineFrame& f) {
  EXPECT_NEAR(f.tangent.norm(), 1.0, 1e-14);
  EXPECT_NEAR(f.x.norm(), 1.0, 1e-14);
  EXPECT_LT(std::abs(f.x.dot(f.tangent)), 1e-14);
  EXPECT_LT((f.x.cross(f.y) - f.tangent).norm(), 1e-14);
}

// M6-2: along two turns of a helix (a = 2, c = 0.5), the RMF equals the analytic Frenet pair
// (n, b) turned by φ(t) = φ₀ − τ·s(t), s = t√(a² + c²): the rotation about the tangent between
// them stays within 1e-8 rad at 200 stations.
TEST(SweepFrames, RotationMinimisingFrameOfAHelixMatchesTheClosedForm) {
  const double a = 2.0, c = 0.5, speed = std::hypot(a, c), tau = c / (a * a + c * c);
  const NurbsCurve3d helix = test::helix_spline(a, c, 2.0, 8001);
  std::vector<double> ts;
  for (int k = 0; k <= 200; ++k) ts.push_back(helix.back() * k / 200);
  const Eigen::Vector3d n0(-1, 0, 0);  // the analytic principal normal at t = 0
  const auto frames = spine_frames(helix, ts, FrameRule::rmf, &n0);
  ASSERT_EQ(frames.size(), ts.size());
  double worst = 0.0;
  for (const SpineFrame& f : frames) {
    expect_orthonormal(f);
    const double t = f.t;
    const Eigen::Vector3d n(-std::cos(t), -std::sin(t), 0);
    const Eigen::Vector3d b =
        Eigen::Vector3d(-a * std::sin(t), a * std::cos(t), c).cross(n) / speed;
    const double phi = -tau * speed * t;  // φ₀ = 0: the first x is n(0)
    const Eigen::Vector3d x = std::cos(phi) * n + std::sin(phi) * b;
    const Eigen::Vector3d xp = (x - x.dot(f.tangent) * f.tangent).normalized();
    worst = std::max(worst, std::abs(std::atan2(xp.cross(f.x).dot(f.tangent), xp.dot(f.x))));
  }
  RecordProperty("max_rotation_error_rad", test::sci(worst));
  EXPECT_LT(worst, 1e-8);
}

// The Frenet frame of a circle: x = n points at the centre, y = b is the plane normal.
TEST(SweepFrames, FrenetFrameOfACircle) {
  const NurbsCurve3d c = circle(3.0);
  const auto frames = spine_frames(c, {0.0, 0.1, 0.37, 0.8, 1.0}, FrameRule::frenet);
  for (const SpineFrame& f : frames) {
    expect_orthonormal(f);
    EXPECT_LT((f.x - (Eigen::Vector3d(1, 2, 0) - f.point) / 3.0).norm(), 1e-14);
    EXPECT_LT((f.y - Eigen::Vector3d::UnitZ()).norm(), 1e-14);
  }
}

// On a planar spine the fixed frame keeps y the plane normal and the RMF coincides with it (a
// planar curve's RMF turns with its tangent).
TEST(SweepFrames, FixedFrameOfAPlanarSpineAndItsRmf) {
  const NurbsCurve3d c(
      3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1},
      NurbsCurve3d::Points{{0, 0, 0}, {1, 2, 0}, {2, -1, 0}, {3, 1, 0}, {4, 0, 0}});
  std::vector<double> ts;
  for (int k = 0; k <= 20; ++k) ts.push_back(k / 20.0);
  const auto fixed = spine_frames(c, ts, FrameRule::fixed);
  const auto rmf = spine_frames(c, ts, FrameRule::rmf);
  for (std::size_t k = 0; k < ts.size(); ++k) {
    expect_orthonormal(fixed[k]);
    EXPECT_NEAR(std::abs(fixed[k].y.z()), 1.0, 1e-14);
    EXPECT_LT((rmf[k].x - fixed[k].x).norm(), 1e-9) << ts[k];
  }
}

// A given initial x keeps the fixed rule's x constant up to its projection on the normal plane.
TEST(SweepFrames, FixedFrameWithAGivenDirection) {
  const NurbsCurve3d helix = test::helix_spline(2.0, 0.5, 0.25, 101);
  const Eigen::Vector3d X(0, 0, 1);
  const auto frames = spine_frames(helix, {0.0, 0.5, 1.0, 1.5}, FrameRule::fixed, &X);
  for (const SpineFrame& f : frames) {
    expect_orthonormal(f);
    EXPECT_LT((f.x - (X - X.dot(f.tangent) * f.tangent).normalized()).norm(), 1e-14);
  }
}

TEST(SweepFrames, Refusals) {
  const NurbsCurve3d line(1, {0, 0, 1, 1}, NurbsCurve3d::Points{{0, 0, 0}, {1, 1, 1}});
  EXPECT_THROW(spine_frames(line, {0.0, 0.5}, FrameRule::frenet), InputError);
  EXPECT_THROW(spine_frames(line, {}, FrameRule::rmf), InputError);
  EXPECT_THROW(spine_frames(line, {0.5, 0.2}, FrameRule::rmf), InputError);
  EXPECT_THROW(spine_frames(line, {1.5}, FrameRule::rmf), InputError);
  const auto frames = spine_frames(line, {0.0, 0.5, 1.0}, FrameRule::rmf);
  for (const SpineFrame& f : frames) EXPECT_LT((f.x - frames[0].x).norm(), 1e-15);
}

}  // namespace
}  // namespace polarform
