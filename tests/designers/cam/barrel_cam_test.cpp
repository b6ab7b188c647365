// Barrel cam: track point and derivatives, the track height function, and groove wall points that
// satisfy the envelope condition of the roller surface.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/cam/barrel_cam.h"
#include "src/error.h"
#include "tests/designers/cam/cam_test_support.h"

namespace polarform {
namespace {

constexpr double pi = std::numbers::pi;

CamProgram barrel_program() {
  SegmentSpec rise, dwell, ret;
  rise.kind = SegmentKind::Rise, rise.start = 0, rise.end = pi / 2, rise.lift = 30, rise.law = MotionLaw::Polynomial345;
  dwell.kind = SegmentKind::Dwell, dwell.start = pi / 2, dwell.end = pi;
  ret.kind = SegmentKind::Return, ret.start = pi, ret.end = 2 * pi, ret.lift = 30, ret.law = MotionLaw::ModifiedSine;
  return CamProgram({rise, dwell, ret});
}

TEST(BarrelCam, TrackPointDerivativesAndHeight) {
  for (Rotation rot : {Rotation::CounterClockwise, Rotation::Clockwise}) {
    const BarrelCam cam(barrel_program(), 60.0, 5.0, 8.0, rot);
    const PolarFunction z = cam.track_height();
    for (int i = 1; i < 100; ++i) {
      const double theta = 2 * pi * (i + 0.3) / 100;
      Eigen::Vector3d p[4];
      cam.track_point(theta, 3, p);
      EXPECT_NEAR(std::hypot(p[0].x(), p[0].y()), 60.0, 1e-12);
      const double phi = follower_polar_angle(theta, rot);
      EXPECT_NEAR(z(phi), p[0].z(), 1e-12);
      EXPECT_NEAR(std::atan2(p[0].y(), p[0].x()), std::remainder(phi, 2 * pi), 1e-12);
      for (int k = 1; k <= 3; ++k)
        for (int c = 0; c < 3; ++c) {
          const double fd = test::central_difference([&](double t) {
            Eigen::Vector3d q[4];
            cam.track_point(t, 3, q);
            return q[k - 1](c);
          }, theta, 1e-4);
          EXPECT_NEAR(p[k](c), fd, 1e-6 * std::max(1.0, std::abs(fd)));
        }
    }
  }
}

// Each wall point lies at Rr from the roller axis, and the wall curve traced at fixed t moves
// perpendicular to the roller's surface normal there (envelope condition).
TEST(BarrelCam, GrooveWallPointsAreOnTheEnvelope) {
  const BarrelCam cam(barrel_program(), 60.0, 0.0, 8.0);
  for (int side : {1, -1}) {
    for (double t : {55.0, 60.0, 68.0}) {
      for (int i = 0; i < 50; ++i) {
        const double theta = 2 * pi * (i + 0.4) / 50;
        const Eigen::Vector3d p = cam.groove_wall_point(theta, t, side);
        const Eigen::Vector3d u = cam.roller_axis(theta);
        Eigen::Vector3d track[1];
        cam.track_point(theta, 0, track);
        const Eigen::Vector3d axis_point(0, 0, track[0].z());
        const Eigen::Vector3d radial = (p - axis_point) - (p - axis_point).dot(u) * u;
        EXPECT_NEAR(radial.norm(), 8.0, 1e-12);
        EXPECT_NEAR((p - axis_point).dot(u), t, 1e-12);
        EXPECT_EQ(radial.z() > 0, side > 0);
        Eigen::Vector3d velocity;
        for (int c = 0; c < 3; ++c)
          velocity(c) = test::central_difference([&](double x) { return cam.groove_wall_point(x, t, side)(c); }, theta, 1e-4);
        EXPECT_NEAR(velocity.dot(radial / 8.0), 0.0, 1e-7 * velocity.norm());
      }
    }
  }
  double s[2];
  barrel_program().derivatives(0.7, 1, s);
  EXPECT_NEAR(cam.pressure_angle(0.7, 60.0), std::atan(s[1] / 60.0), 1e-15);
  EXPECT_THROW(BarrelCam(barrel_program(), 60.0, 0.0, 70.0), InputError);
}

}  // namespace
}  // namespace polarform
