// Surface interrogation (MIT §8.2.4, spec M5 / B6): Gaussian and mean curvature of an exact sphere
// and cylinder against their closed forms, the signs on a saddle, and reflection lines of a
// cylinder constant along its rulings.
#include "src/nurbs/surface_curvature.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "src/base/arc_curves.h"
#include "src/nurbs/extrusion.h"
#include "src/nurbs/surface_of_revolution.h"

namespace polarform {
namespace {

// A 3D copy of a planar arc scaled by r, in the xz-plane (x, 0, y) or the xy-plane.
NurbsCurve3d arc3(double start, double sweep, double r, bool xz) {
  const NurbsCurve2d a = rqb_arc(start, sweep);
  NurbsCurve3d::Points p;
  for (const Eigen::Vector2d& q : a.control_points())
    p.push_back(xz ? Eigen::Vector3d(r * q.x(), 0, r * q.y())
                   : Eigen::Vector3d(r * q.x(), r * q.y(), 0));
  return NurbsCurve3d(a.degree(), a.knots(), p, a.weights());
}

TEST(SurfaceCurvature, SphereHasKOneOverRSquaredAndHOneOverR) {
  const double R = 7.0;
  // A 120° meridian arc from −60° to 60° (away from the poles), revolved a full turn.
  const NurbsSurface s = revolve(arc3(-std::numbers::pi / 3, 2 * std::numbers::pi / 3, R, true),
                                 Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  for (int a = 0; a <= 10; ++a)
    for (int b = 0; b <= 10; ++b) {
      const double u = s.front_u() + (s.back_u() - s.front_u()) * a / 10;
      const double v = s.front_v() + (s.back_v() - s.front_v()) * b / 10;
      const SurfaceCurvature c = surface_curvature(s, u, v);
      ASSERT_FALSE(c.degenerate);
      EXPECT_NEAR(c.gaussian, 1 / (R * R), 1e-9 / (R * R));
      EXPECT_NEAR(std::abs(c.mean), 1 / R, 1e-9 / R);
      EXPECT_NEAR(c.absolute(), 2 / R, 1e-9 / R);
    }
}

TEST(SurfaceCurvature, CylinderHasZeroGaussianCurvature) {
  const double R = 3.0;
  const NurbsSurface s = extrude(arc3(0.2, 2.5, R, false), Eigen::Vector3d::UnitZ(), 0, 10);
  for (int a = 0; a <= 20; ++a)
    for (int b = 0; b <= 4; ++b) {
      const double u = s.front_u() + (s.back_u() - s.front_u()) * a / 20;
      const SurfaceCurvature c = surface_curvature(s, u, b / 4.0);
      EXPECT_NEAR(c.gaussian, 0.0, 1e-12);
      EXPECT_NEAR(std::abs(c.mean), 1 / (2 * R), 1e-12);
    }
}

TEST(SurfaceCurvature, SaddleIsHyperbolicAndADomeElliptic) {
  // z = x·y on [−1, 1]² (bilinear) and a dome z = −(x² + y²)/4 (a biquadratic Bézier).
  const Knots k1{0, 0, 1, 1}, k2{0, 0, 0, 1, 1, 1};
  const NurbsSurface saddle(1, 1, k1, k1, {{-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}, {1, 1, 1}});
  NurbsSurface::Points dome;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double x = i - 1.0, y = j - 1.0;
      // Control values of −x²/4 on a quadratic Bézier over [−1, 1]: −1/4, 1/4, −1/4.
      const double fx = i == 1 ? 0.25 : -0.25, fy = j == 1 ? 0.25 : -0.25;
      dome.push_back({x, y, fx + fy});
    }
  const NurbsSurface d(2, 2, k2, k2, dome);
  for (const double u : {0.2, 0.5, 0.9})
    for (const double v : {0.1, 0.5, 0.7}) {
      EXPECT_LT(surface_curvature(saddle, u, v).gaussian, 0.0);
      EXPECT_GT(surface_curvature(d, u, v).gaussian, 0.0);
    }
}

TEST(ReflectionLines, AreStraightAndParallelOnACylinder) {
  const NurbsSurface s = extrude(arc3(0.3, 2.0, 4.0, false), Eigen::Vector3d::UnitZ(), 0, 10);
  ReflectionLights l;
  l.view = Eigen::Vector3d(-0.2, -1, -0.3);
  l.line = Eigen::Vector3d::UnitZ();
  l.plane_normal = Eigen::Vector3d(0.1, 1, 0).normalized();
  l.plane_offset = 20;
  l.spacing = 0.5;
  int lit = 0;
  for (int a = 0; a <= 10; ++a) {
    const double u = s.front_u() + (s.back_u() - s.front_u()) * a / 10;
    const double first = reflection_line_value(s.point(u, 0), s.normal(u, 0), l);
    lit += std::isfinite(first);
    for (int b = 1; b <= 10; ++b) {
      const double value = reflection_line_value(s.point(u, b / 10.0), s.normal(u, b / 10.0), l);
      if (std::isnan(first))
        EXPECT_TRUE(std::isnan(value));
      else
        EXPECT_NEAR(value, first, 1e-12 * std::max(1.0, std::abs(first)));
    }
  }
  EXPECT_GE(lit, 5);  // most of the arc sees the lights
}

}  // namespace
}  // namespace polarform
