// extrude (Kantz 2003, (3.11) with a linear trajectory): the surface equals C(u) + v·d on a grid,
// for a rational circle and a non-rational cubic, with degree (p, 1) and C's knots; bad ranges
// and directions are refused.
#include "src/nurbs/extrusion.h"

#include <gtest/gtest.h>

#include <cmath>

#include "src/error.h"

namespace polarform {
namespace {

// A full circle of radius r in the plane z = 1 (four rational quadratic arcs).
NurbsCurve3d tilted_circle(double r) {
  const double w = std::sqrt(0.5);
  NurbsCurve3d::Points P{{r, 0, 1},   {r, r, 1},  {0, r, 1},  {-r, r, 1}, {-r, 0, 1},
                         {-r, -r, 1}, {0, -r, 1}, {r, -r, 1}, {r, 0, 1}};
  return NurbsCurve3d(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, P,
                      {1, w, 1, w, 1, w, 1, w, 1});
}

void expect_closed_form(const NurbsCurve3d& c, const Eigen::Vector3d& d, double v0, double v1) {
  const NurbsSurface S = extrude(c, d, v0, v1);
  EXPECT_EQ(S.degree_u(), c.degree());
  EXPECT_EQ(S.degree_v(), 1);
  EXPECT_EQ(S.knots_u(), c.knots());
  double worst = 0.0;
  for (int a = 0; a <= 40; ++a)
    for (int b = 0; b <= 10; ++b) {
      const double u = c.front() + (c.back() - c.front()) * a / 40.0;
      const double v = v0 + (v1 - v0) * b / 10.0;
      worst = std::max(worst, (S.point(u, v) - (c.point(u) + v * d)).norm());
    }
  EXPECT_LE(worst, 1e-13);
}

TEST(Extrusion, RationalCircleEqualsClosedForm) {
  expect_closed_form(tilted_circle(12.5), Eigen::Vector3d(0.3, -0.2, 0.9).normalized(), -4.0, 17.0);
}

TEST(Extrusion, CubicEqualsClosedForm) {
  const NurbsCurve3d c(3, {0, 0, 0, 0, 0.4, 1, 1, 1, 1},
                       {{0, 0, 0}, {2, 3, 1}, {5, -1, 0}, {7, 2, -2}, {9, 0, 1}});
  expect_closed_form(c, Eigen::Vector3d(1, 2, 3), 0.5, 2.0);
}

TEST(Extrusion, NormalIsCurveTangentCrossDirection) {
  const Eigen::Vector3d d(0, 0, 5);
  const NurbsSurface S = extrude(tilted_circle(3), d, 0, 1);
  for (double u : {0.1, 0.37, 0.8}) {
    const Eigen::Vector3d n = S.normal(u, 0.5);
    const Eigen::Vector3d radial = (S.point(u, 0.5) - Eigen::Vector3d(0, 0, 1 + 2.5)).normalized();
    EXPECT_NEAR(n.dot(radial), 1.0, 1e-12);  // counter-clockwise C: outward
  }
}

TEST(Extrusion, RefusesBadRangeAndDirection) {
  const NurbsCurve3d c = tilted_circle(1);
  EXPECT_THROW(extrude(c, Eigen::Vector3d::UnitZ(), 1, 1), InputError);
  EXPECT_THROW(extrude(c, Eigen::Vector3d::UnitZ(), 0, NAN), InputError);
  EXPECT_THROW(extrude(c, Eigen::Vector3d::Zero(), 0, 1), InputError);
}

}  // namespace
}  // namespace polarform
