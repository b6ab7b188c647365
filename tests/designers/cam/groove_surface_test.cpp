// Groove wall surfaces of a barrel cam: the NURBS wall lies within the tolerance of the exact
// envelope (distances found here by a Gauss–Newton foot-point search on groove_wall_point, not by
// the library's own measure), its x, y part is exact, it closes in u, and zero lift gives planes.
#include "designers/cam/groove_surface.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <string>

#include "designers/cam/groove_wall.h"
#include "src/error.h"

namespace polarform {
namespace {

constexpr double pi = std::numbers::pi;

CamProgram groove_program() {
  SegmentSpec rise, dwell, ret;
  rise.kind = SegmentKind::Rise, rise.start = 0, rise.end = pi / 2, rise.lift = 30,
  rise.law = MotionLaw::Polynomial345;
  dwell.kind = SegmentKind::Dwell, dwell.start = pi / 2, dwell.end = pi;
  ret.kind = SegmentKind::Return, ret.start = pi, ret.end = 2 * pi, ret.lift = 30,
  ret.law = MotionLaw::ModifiedSine;
  return CamProgram({rise, dwell, ret});
}

// Distance from p to the exact wall: the nearest of 400 samples in θ around p's polar angle at
// t = |p.xy|, then Gauss–Newton on (θ, t) with central-difference Jacobians of groove_wall_point.
double wall_distance(const BarrelCam& cam, int side, const Eigen::Vector3d& p) {
  const double sigma = cam.rotation() == Rotation::CounterClockwise ? 1 : -1;
  const double theta0 = sigma * (pi / 2 - std::atan2(p.y(), p.x()));
  double theta = theta0, t = std::hypot(p.x(), p.y()), best = INFINITY;
  for (int i = -200; i <= 200; ++i) {
    const double th = theta0 + 0.4 * i / 200;
    const double d = (cam.groove_wall_point(th, t, side) - p).norm();
    if (d < best) best = d, theta = th;
  }
  for (int it = 0; it < 30; ++it) {
    const double h = 1e-6;
    const Eigen::Vector3d w = cam.groove_wall_point(theta, t, side);
    Eigen::Matrix<double, 3, 2> J;
    J.col(0) =
        (cam.groove_wall_point(theta + h, t, side) - cam.groove_wall_point(theta - h, t, side)) /
        (2 * h);
    J.col(1) =
        (cam.groove_wall_point(theta, t + h, side) - cam.groove_wall_point(theta, t - h, side)) /
        (2 * h);
    const Eigen::Vector2d step = (J.transpose() * J).ldlt().solve(J.transpose() * (p - w));
    theta += step(0), t += step(1);
    if (step.norm() < 1e-13) break;
  }
  return (cam.groove_wall_point(theta, t, side) - p).norm();
}

TEST(GrooveSurface, WithinToleranceOfTheExactWallBothWays) {
  struct Case {
    Rotation rot;
    int side;
    double tol;
  };
  for (const Case c : {Case{Rotation::CounterClockwise, 1, 1e-3},
                       {Rotation::CounterClockwise, -1, 1e-3},
                       {Rotation::Clockwise, 1, 1e-3},
                       {Rotation::Clockwise, -1, 1e-3},
                       {Rotation::CounterClockwise, 1, 1e-5},
                       {Rotation::Clockwise, -1, 1e-5}}) {
    SCOPED_TRACE("side " + std::to_string(c.side) + ", tolerance " + std::to_string(c.tol));
    const BarrelCam cam(groove_program(), 60.0, 5.0, 8.0, c.rot);
    const GrooveSurface g = groove_surface(cam, c.side, {55.0, 65.0, c.tol});
    const NurbsSurface& S = g.surface;
    EXPECT_LE(g.max_error, c.tol);
    EXPECT_LE(g.fit_error, 0.9 * c.tol);
    double surface_to_wall = 0.0, wall_to_surface = 0.0;
    for (int i = 0; i < 200; ++i)
      for (int j = 0; j < 20; ++j) {
        const double u = S.front_u() + (S.back_u() - S.front_u()) * (i + 0.37) / 200;
        const double v = 55.0 + 10.0 * j / 19;
        surface_to_wall = std::max(surface_to_wall, wall_distance(cam, c.side, S.point(u, v)));
      }
    // Wall points at radius t (inside the wall's ρ range) against the surface point of the same
    // polar angle and radius: an upper bound of the distance to the surface.
    for (int i = 0; i < 200; ++i)
      for (int j = 0; j < 20; ++j) {
        const Eigen::Vector3d w =
            cam.groove_wall_point(2 * pi * (i + 0.61) / 200, 55.5 + 9.0 * j / 19, c.side);
        const double rho = std::hypot(w.x(), w.y());
        ASSERT_GE(rho, 55.0);
        ASSERT_LE(rho, 65.0);
        const Eigen::Vector3d s = S.point(g.base.parameter(std::atan2(w.y(), w.x())), rho);
        wall_to_surface = std::max(wall_to_surface, (s - w).norm());
      }
    EXPECT_LE(surface_to_wall, c.tol);
    EXPECT_LE(wall_to_surface, c.tol);
    EXPECT_GT(surface_to_wall, 1e-3 * c.tol);  // a fit, not an identity
    EXPECT_EQ(S.degree_u(), 9);
    EXPECT_EQ(S.degree_v(), 3);
  }
}

TEST(GrooveSurface, RadialIsoCurvesLieOnCylindersAndTheSeamCloses) {
    const BarrelCam cam(groove_program(), 60.0, 5.0, 8.0);
    const GrooveSurface g = groove_surface(cam, 1, {52.0, 66.0, 1e-4});
    const NurbsSurface& S = g.surface;
    for (double v : {52.0, 59.5, 66.0}) {
      for (int i = 0; i <= 400; ++i) {
        const Eigen::Vector3d p = S.point(S.front_u() + (S.back_u() - S.front_u()) * i / 400, v);
        EXPECT_NEAR(std::hypot(p.x(), p.y()), v, 1e-12);
      }
      EXPECT_LT((S.point(S.front_u(), v) - S.point(S.back_u(), v)).norm(), 1e-12);
    }
    EXPECT_LE(g.max_error, 1e-4);
  }

  TEST(GrooveSurface, ZeroLiftGivesPlanarAnnuli) {
    SegmentSpec dwell;
    dwell.kind = SegmentKind::Dwell, dwell.start = 0, dwell.end = 2 * pi;
    const BarrelCam cam(CamProgram({dwell}), 60.0, 5.0, 8.0);
    for (int side : {1, -1}) {
      const GrooveSurface g = groove_surface(cam, side, {50.0, 70.0, 1e-6});
      EXPECT_EQ(g.height.degree_u(), 0);
      EXPECT_EQ(g.height.degree_v(), 0);
      EXPECT_EQ(g.surface.degree_u(), 4);
      EXPECT_EQ(g.surface.degree_v(), 1);
      EXPECT_LE(g.max_error, 1e-12);
      for (int i = 0; i <= 100; ++i)
        for (int j = 0; j <= 4; ++j) {
          const double u =
              g.surface.front_u() + (g.surface.back_u() - g.surface.front_u()) * i / 100;
          const Eigen::Vector3d p = g.surface.point(u, 50.0 + 5.0 * j);
          EXPECT_NEAR(p.z(), 5.0 + side * 8.0, 1e-12);
          EXPECT_NEAR(std::hypot(p.x(), p.y()), 50.0 + 5.0 * j, 1e-12);
        }
    }
  }

  TEST(GrooveSurface, WallHeightMatchesTheContactPoint) {
    const BarrelCam cam(groove_program(), 60.0, 5.0, 8.0, Rotation::Clockwise);
    for (int side : {1, -1}) {
      const GrooveWall wall(cam, side);
      for (int i = 0; i < 50; ++i) {
        const Eigen::Vector3d w = cam.groove_wall_point(2 * pi * (i + 0.2) / 50, 57.0, side);
        const WallPoint c = wall.at(std::atan2(w.y(), w.x()), std::hypot(w.x(), w.y()));
        EXPECT_NEAR(c.z, w.z(), 1e-10);
        EXPECT_NEAR(c.t, 57.0, 1e-10);
      }
    }
  }

  TEST(GrooveSurface, RejectsBadRadiiAndSides) {
    const BarrelCam cam(groove_program(), 60.0, 5.0, 8.0);
    EXPECT_THROW(groove_surface(cam, 0, {55.0, 65.0, 1e-3}), InputError);
    EXPECT_THROW(groove_surface(cam, 1, {10.0, 65.0, 1e-3}), InputError);  // < √2·Rr
    EXPECT_THROW(groove_surface(cam, 1, {65.0, 55.0, 1e-3}), InputError);
    EXPECT_THROW(groove_surface(cam, 1, {55.0, 65.0, 0.0}), InputError);
  }

}  // namespace
}  // namespace polarform
