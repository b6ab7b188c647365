// ruled_surface and bilinear_surface (NURBS Book §8.2, §8.4; spec B5): the surface equals
// (1 − v)·C0(u) + v·C1(u) on a 101 × 101 grid, for a line against a rational circle arc (the line
// written with the arc's weights) and for two non-rational curves of different degree and knots.
#include "src/nurbs/ruled_surface.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "src/error.h"
#include "tests/src/nurbs/kernel_test_support.h"

namespace polarform {
namespace {

using Eigen::Vector3d;

double closed_form_error(const NurbsCurve3d& c0, const NurbsCurve3d& c1) {
  const NurbsSurface S = ruled_surface(c0, c1);
  EXPECT_EQ(S.degree_v(), 1);
  double worst = 0.0;
  for (int a = 0; a <= 100; ++a)
    for (int b = 0; b <= 100; ++b) {
      const double u = c0.front() + (c0.back() - c0.front()) * a / 100.0, v = b / 100.0;
      worst = std::max(worst, (S.point(u, v) - ((1 - v) * c0.point(u) + v * c1.point(u))).norm());
    }
  return worst;
}

TEST(RuledSurface, LineAgainstCircleArcEqualsClosedForm) {
  // 90° arc of radius 10 (RQB, middle weight cos 45°) and a line above it written with the same
  // weights (its middle point on the segment): equal weight functions, so the loft is exact.
  const double w = std::sqrt(0.5), r = 10.0;
  const NurbsCurve3d arc(2, {0, 0, 0, 1, 1, 1}, {{r, 0, 0}, {r, r, 0}, {0, r, 0}}, {1, w, 1});
  const NurbsCurve3d line(2, {0, 0, 0, 1, 1, 1}, {{2, -3, 6}, {4, 0, 6}, {6, 3, 6}}, {1, w, 1});
  const double err = closed_form_error(line, arc);
  RecordProperty("line_arc_error", test::sci(err));
  EXPECT_LE(err, 1e-14 * r);
  EXPECT_TRUE(ruled_surface(line, arc).is_rational());
}

TEST(RuledSurface, CubicAgainstQuadraticEqualsClosedForm) {
  const NurbsCurve3d c0(3, {0, 0, 0, 0, 0.3, 1, 1, 1, 1},
                        {{0, 0, 0}, {2, 3, 1}, {5, -1, 0}, {7, 2, -2}, {9, 0, 1}});
  const NurbsCurve3d c1(2, {0, 0, 0, 0.5, 0.7, 1, 1, 1},
                        {{0, 5, 3}, {3, 6, 2}, {4, 4, 4}, {8, 7, 3}, {9, 5, 2}});
  const NurbsSurface S = ruled_surface(c0, c1);
  EXPECT_EQ(S.degree_u(), 3);
  const double err = closed_form_error(c0, c1);
  RecordProperty("cubic_quadratic_error", test::sci(err));
  EXPECT_LE(err, 1e-14 * 10);
}

TEST(RuledSurface, RefusesDifferentWeightsAndDomains) {
  const double w = std::sqrt(0.5);
  const NurbsCurve3d arc(2, {0, 0, 0, 1, 1, 1}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, w, 1});
  const NurbsCurve3d line(1, {0, 0, 1, 1}, {{0, 0, 1}, {1, 0, 1}});
  EXPECT_THAT([&] { ruled_surface(line, arc); },
              testing::ThrowsMessage<InputError>(testing::HasSubstr("weight functions differ")));
  const NurbsCurve3d other(1, {0, 0, 2, 2}, {{0, 0, 1}, {1, 0, 1}});
  EXPECT_THROW(ruled_surface(line, other), InputError);
}

TEST(BilinearSurface, EqualsClosedForm) {
  const Vector3d p00(0, 0, 0), p10(3, 0, 1), p01(0, 2, -1), p11(4, 5, 2);
  const NurbsSurface S = bilinear_surface(p00, p10, p01, p11);
  for (int a = 0; a <= 20; ++a)
    for (int b = 0; b <= 20; ++b) {
      const double u = a / 20.0, v = b / 20.0;
      const Vector3d e =
          (1 - u) * (1 - v) * p00 + u * (1 - v) * p10 + (1 - u) * v * p01 + u * v * p11;
      EXPECT_LE((S.point(u, v) - e).norm(), 1e-15 * 8);
    }
}

}  // namespace
}  // namespace polarform
