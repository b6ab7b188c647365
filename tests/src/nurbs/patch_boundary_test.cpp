// boundary_from_loop (Piegl & Tiller 2001, §2; spec P1): four curves in loop order, some running
// backwards and on other domains, come out as u0, u1, v0, v1 on [0, 1] meeting at the corners;
// a gap names its corner; reversed(c)(t) = c(a + b − t).
#include "src/nurbs/patch_boundary.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "src/error.h"

namespace polarform {
namespace {

using Eigen::Vector3d;

// A cubic from a to b on [t0, t1] with one interior knot, bulging by `bulge`.
NurbsCurve3d cubic(const Vector3d& a, const Vector3d& b, const Vector3d& bulge, double t0,
                   double t1) {
  const double m = t0 + 0.4 * (t1 - t0);
  return NurbsCurve3d(
      3, {t0, t0, t0, t0, m, t1, t1, t1, t1},
      {a, a + (b - a) / 4 + bulge, a + (b - a) / 2 + 1.5 * bulge, a + 3 * (b - a) / 4 + bulge, b});
}

const Vector3d c00(0, 0, 0), c10(10, 0, 1), c11(11, 8, 0), c01(-1, 9, 2);

TEST(PatchBoundary, ReversedRunsBackwardsOnTheSameDomain) {
  const NurbsCurve3d c = cubic(c00, c10, Vector3d(0, 1, 2), 2.0, 5.0);
  const NurbsCurve3d r = reversed(c);
  EXPECT_EQ(r.front(), 2.0);
  EXPECT_EQ(r.back(), 5.0);
  for (int k = 0; k <= 100; ++k) {
    const double t = 2.0 + 3.0 * k / 100.0;
    EXPECT_LE((r.point(t) - c.point(7.0 - t)).norm(), 1e-14 * 12);
  }
}

TEST(PatchBoundary, OrdersOrientsAndNormalisesTheLoop) {
  const NurbsCurve3d a = cubic(c00, c10, Vector3d(0, -1, 0), 0, 3);    // u0
  const NurbsCurve3d b = cubic(c10, c11, Vector3d(1, 0, 0), -1, 1);    // v1
  const NurbsCurve3d c = cubic(c11, c01, Vector3d(0, 1, 1), 0, 1);     // u1 backwards
  const NurbsCurve3d d = cubic(c01, c00, Vector3d(-1, 0, 0), 10, 20);  // v0 backwards
  // Given with c0 and c2 running the other way (and c1 too): the result must not change.
  for (const auto& loop : {std::array{a, b, c, d}, std::array{reversed(a), reversed(b), c, d},
                           std::array{a, reversed(b), reversed(c), reversed(d)}}) {
    const PatchBoundary pb = boundary_from_loop(loop, 1e-9);
    for (const NurbsCurve3d* e : {&pb.u0, &pb.u1, &pb.v0, &pb.v1}) {
      EXPECT_EQ(e->front(), 0.0);
      EXPECT_EQ(e->back(), 1.0);
    }
    EXPECT_LE((pb.u0.point(0) - c00).norm(), 1e-14);
    EXPECT_LE((pb.u0.point(1) - c10).norm(), 1e-14);
    EXPECT_LE((pb.u1.point(0) - c01).norm(), 1e-14);
    EXPECT_LE((pb.u1.point(1) - c11).norm(), 1e-14);
    EXPECT_LE((pb.v0.point(0) - c00).norm(), 1e-14);
    EXPECT_LE((pb.v0.point(1) - c01).norm(), 1e-14);
    EXPECT_LE((pb.v1.point(0) - c10).norm(), 1e-14);
    EXPECT_LE((pb.v1.point(1) - c11).norm(), 1e-14);
    for (int k = 0; k <= 100; ++k) {
      const double s = k / 100.0;
      EXPECT_LE((pb.u0.point(s) - a.point(3 * s)).norm(), 1e-13);
      EXPECT_LE((pb.v1.point(s) - b.point(-1 + 2 * s)).norm(), 1e-13);
      EXPECT_LE((pb.u1.point(s) - c.point(1 - s)).norm(), 1e-13);
      EXPECT_LE((pb.v0.point(s) - d.point(20 - 10 * s)).norm(), 1e-13);
    }
  }
}

TEST(PatchBoundary, SnapsCornersWithinTheTolerance) {
  const Vector3d e(0, 0, 4e-10);
  const PatchBoundary pb = boundary_from_loop(
      {cubic(c00, c10, Vector3d(0, -1, 0), 0, 1), cubic(c10 + e, c11, Vector3d(1, 0, 0), 0, 1),
       cubic(c11, c01, Vector3d(0, 1, 1), 0, 1), cubic(c01, c00, Vector3d(-1, 0, 0), 0, 1)},
      1e-9);
  EXPECT_EQ(pb.u0.point(1), pb.v1.point(0));
  EXPECT_LE((pb.u0.point(1) - (c10 + e / 2)).norm(), 1e-15);
}

TEST(PatchBoundary, GapNamesTheCorner) {
  const std::array loop{cubic(c00, c10, Vector3d(0, -1, 0), 0, 1),
                        cubic(c10, c11, Vector3d(1, 0, 0), 0, 1),
                        cubic(c11, c01 + Vector3d(0.01, 0, 0), Vector3d(0, 1, 1), 0, 1),
                        cubic(c01, c00, Vector3d(-1, 0, 0), 0, 1)};
  EXPECT_THAT([&] { boundary_from_loop(loop, 1e-9); },
              testing::ThrowsMessage<InputError>(testing::HasSubstr("corner 3")));
}

TEST(PatchBoundary, RefusesRationalCurves) {
  std::array loop{
      cubic(c00, c10, Vector3d(0, -1, 0), 0, 1), cubic(c10, c11, Vector3d(1, 0, 0), 0, 1),
      cubic(c11, c01, Vector3d(0, 1, 1), 0, 1), cubic(c01, c00, Vector3d(-1, 0, 0), 0, 1)};
  loop[2] = NurbsCurve3d(3, loop[2].knots(), loop[2].control_points(), {1, 2, 1, 1, 1});
  EXPECT_THAT([&] { boundary_from_loop(loop, 1e-9); },
              testing::ThrowsMessage<InputError>(testing::HasSubstr("curve 2 is rational")));
}

}  // namespace
}  // namespace polarform
