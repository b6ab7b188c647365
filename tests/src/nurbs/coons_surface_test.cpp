// bilinear_coons and bicubic_coons (Piegl & Tiller 2001, §2.1–2.2; spec P1, P2 check 1): boundary
// interpolation on 1001 samples per edge, reproduction of bilinear patches, ruled surfaces and
// (with exact cross derivatives) bicubic patches, and the closed form of a bicubic Bezier patch's
// bilinear-Coons interior control points; parameters recovered by projection (P1 check 4).
#include "src/nurbs/coons_surface.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>

#include "src/error.h"
#include "src/nurbs/knot_refinement.h"
#include "src/nurbs/point_inversion.h"
#include "src/nurbs/ruled_surface.h"
#include "tests/src/nurbs/kernel_test_support.h"
#include "tests/support/src/patch_test_support.h"

namespace polarform {
namespace {

using Eigen::Vector3d;

double grid_distance(const NurbsSurface& a, const NurbsSurface& b, int n = 100) {
  double worst = 0.0;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      worst = std::max(
          worst,
          (a.point(i / double(n), j / double(n)) - b.point(i / double(n), j / double(n))).norm());
  return worst;
}

NurbsSurface::Points random_net(std::mt19937& rng, int n, double size) {
  std::uniform_real_distribution<double> c(-0.15 * size, 0.15 * size);
  NurbsSurface::Points P;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      P.push_back(Vector3d(size * i / (n - 1.0) + c(rng), size * j / (n - 1.0) + c(rng), c(rng)));
  return P;
}

// A B-spline loop of mixed degrees and knots: the four edges of a random (3, 2) surface.
NurbsSurface mixed_surface(std::mt19937& rng) {
  const Knots U{0, 0, 0, 0, 0.3, 0.55, 1, 1, 1, 1}, V{0, 0, 0, 0.4, 1, 1, 1};
  NurbsSurface::Points P;
  std::uniform_real_distribution<double> c(-2.0, 2.0);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 4; ++j) P.push_back(Vector3d(4.0 * i + c(rng), 3.0 * j + c(rng), c(rng)));
  return NurbsSurface(3, 2, U, V, P);
}

TEST(BilinearCoons, InterpolatesTheBoundary) {
  std::mt19937 rng(20);
  const NurbsSurface s = mixed_surface(rng);
  const PatchBoundary b = test::surface_boundary(s);
  const NurbsSurface S = bilinear_coons(b);
  EXPECT_EQ(S.degree_u(), 3);
  EXPECT_EQ(S.degree_v(), 2);
  const double size = test::net_diagonal(s);
  double worst = 0.0;
  for (int k = 0; k <= 1000; ++k) {
    const double t = k / 1000.0;
    worst = std::max(
        {worst, (S.point(t, 0) - b.u0.point(t)).norm(), (S.point(t, 1) - b.u1.point(t)).norm(),
         (S.point(0, t) - b.v0.point(t)).norm(), (S.point(1, t) - b.v1.point(t)).norm()});
  }
  RecordProperty("boundary_error_rel", test::sci(worst / size));
  EXPECT_LE(worst, 1e-14 * size);
}

TEST(BilinearCoons, ReproducesBilinearPatches) {
  const Vector3d p00(0, 0, 0), p10(7, 1, 2), p01(-1, 5, 3), p11(8, 6, -2);
  const NurbsSurface B = bilinear_surface(p00, p10, p01, p11);
  // Edges given as quadratics with an interior knot: still the straight edges.
  const auto edge = [](const Vector3d& a, const Vector3d& b) {
    return NurbsCurve3d(2, {0, 0, 0, 0.3, 1, 1, 1}, {a, a + 0.15 * (b - a), a + 0.65 * (b - a), b});
  };
  const NurbsSurface S =
      bilinear_coons({edge(p00, p10), edge(p01, p11), edge(p00, p01), edge(p10, p11)});
  const double err = grid_distance(S, B);
  RecordProperty("bilinear_error", test::sci(err));
  EXPECT_LE(err, 1e-14 * 10);
}

TEST(BilinearCoons, ReproducesRuledSurfacesInEitherDirection) {
  const NurbsCurve3d c0(3, {0, 0, 0, 0, 0.3, 1, 1, 1, 1},
                        {{0, 0, 0}, {2, 3, 1}, {5, -1, 0}, {7, 2, -2}, {9, 0, 1}});
  const NurbsCurve3d c1(2, {0, 0, 0, 0.5, 0.7, 1, 1, 1},
                        {{0, 5, 3}, {3, 6, 2}, {4, 4, 4}, {8, 7, 3}, {9, 5, 2}});
  const auto line = [](const Vector3d& a, const Vector3d& b) {
    return NurbsCurve3d(1, {0, 0, 1, 1}, {a, b});
  };
  const NurbsSurface R = ruled_surface(c0, c1);
  const NurbsSurface along_u =
      bilinear_coons({c0, c1, line(c0.point(0), c1.point(0)), line(c0.point(1), c1.point(1))});
  const NurbsSurface along_v =
      bilinear_coons({line(c0.point(0), c1.point(0)), line(c0.point(1), c1.point(1)), c0, c1});
  double worst_u = grid_distance(along_u, R), worst_v = 0.0;
  for (int i = 0; i <= 100; ++i)
    for (int j = 0; j <= 100; ++j)
      worst_v = std::max(
          worst_v, (along_v.point(j / 100.0, i / 100.0) - R.point(i / 100.0, j / 100.0)).norm());
  RecordProperty("ruled_error_u", test::sci(worst_u));
  RecordProperty("ruled_error_v", test::sci(worst_v));
  EXPECT_LE(worst_u, 1e-14 * 10);
  EXPECT_LE(worst_v, 1e-14 * 10);
}

// P&T 2001, §2.1 on a bicubic Bezier patch: C_ij = (1−j/3)P_i0 + (j/3)P_i3 + (1−i/3)P_0j +
// (i/3)P_3j − bilinear(P00, P30, P03, P33)(i/3, j/3).
TEST(BilinearCoons, BicubicBezierInteriorClosedForm) {
  std::mt19937 rng(3);
  const NurbsSurface::Points P = random_net(rng, 4, 10.0);
  const auto p = [&](int i, int j) { return P[4 * i + j]; };
  const NurbsSurface S = bilinear_coons(test::surface_boundary(test::bezier_patch(P)));
  ASSERT_EQ(S.size_u(), 4);
  ASSERT_EQ(S.size_v(), 4);
  double worst = 0.0, size = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double s = i / 3.0, t = j / 3.0;
      const Vector3d c = (1 - t) * p(i, 0) + t * p(i, 3) + (1 - s) * p(0, j) + s * p(3, j) -
                         ((1 - s) * (1 - t) * p(0, 0) + s * (1 - t) * p(3, 0) +
                          (1 - s) * t * p(0, 3) + s * t * p(3, 3));
      worst = std::max(worst, (S.control_point(i, j) - c).norm());
      size = std::max(size, c.norm());
    }
  RecordProperty("closed_form_error_rel", test::sci(worst / size));
  EXPECT_LE(worst, 1e-15 * size);
}

// Spec P1 check 4 (exact route): 10^4 points at known (u, v) on a Coons patch come back from
// SurfaceProjector with their parameters.
TEST(BilinearCoons, ParametersRecoveredByProjection) {
  std::mt19937 rng(22);
  const NurbsSurface S = bilinear_coons(test::surface_boundary(mixed_surface(rng)));
  const SurfaceProjector projector(S);
  std::uniform_real_distribution<double> t(0.0, 1.0);
  double worst = 0.0;
  for (int k = 0; k < 10000; ++k) {
    const double u = t(rng), v = t(rng);
    const SurfaceProjection p = projector.project(S.point(u, v));
    worst = std::max({worst, std::abs(p.u - u), std::abs(p.v - v)});
  }
  RecordProperty("parameter_error", test::sci(worst));
  EXPECT_LE(worst, 1e-9);
}

TEST(BilinearCoons, RefusesRationalBoundaries) {
  const NurbsCurve3d r(2, {0, 0, 0, 1, 1, 1}, {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {1, 0.7, 1});
  EXPECT_THAT(
      [&] {
        bilinear_coons({r, r, r, r});
      },
      testing::ThrowsMessage<InputError>(testing::HasSubstr("is rational")));
}

// Spec P2 check 1: the Boolean sum of cubic Hermite projectors reproduces bicubics, also when the
// patch is written with interior knots (boundaries and derivatives then carry them).
TEST(BicubicCoons, ReproducesBicubicPatchWithExactCrossDerivatives) {
  std::mt19937 rng(7);
  const NurbsSurface bez = test::bezier_patch(random_net(rng, 4, 10.0));
  const NurbsSurface refined(refine_knots_v(refine_knots_u(bez.homogeneous(), {0.3, 0.6}), {0.5}));
  for (const NurbsSurface* s : {&bez, &refined}) {
    const NurbsSurface S =
        bicubic_coons(test::surface_boundary(*s), test::surface_cross_derivatives(*s));
    EXPECT_EQ(S.degree_u(), 3);
    EXPECT_EQ(S.degree_v(), 3);
    const double err = grid_distance(S, *s) / test::net_diagonal(*s);
    RecordProperty(s == &bez ? "bezier_error_rel" : "refined_error_rel", test::sci(err));
    EXPECT_LE(err, 1e-13);
  }
}

TEST(BicubicCoons, InterpolatesBoundaryAndCrossDerivatives) {
  std::mt19937 rng(21);
  const NurbsSurface s = mixed_surface(rng);
  const PatchBoundary b = test::surface_boundary(s);
  const CrossDerivatives d = test::surface_cross_derivatives(s);
  const NurbsSurface S = bicubic_coons(b, d);
  EXPECT_EQ(S.degree_u(), 3);
  EXPECT_EQ(S.degree_v(), 3);
  const double size = test::net_diagonal(s);
  double worst = 0.0;
  for (int k = 0; k <= 1000; ++k) {
    const double t = k / 1000.0;
    const auto at = [&](double u, double v) { return S.derivatives(u, v, 1); };
    worst = std::max(
        {worst, (S.point(t, 0) - b.u0.point(t)).norm(), (S.point(t, 1) - b.u1.point(t)).norm(),
         (S.point(0, t) - b.v0.point(t)).norm(), (S.point(1, t) - b.v1.point(t)).norm(),
         (at(t, 0)[1] - d.dv0.point(t)).norm(), (at(t, 1)[1] - d.dv1.point(t)).norm(),
         (at(0, t)[2] - d.du0.point(t)).norm(), (at(1, t)[2] - d.du1.point(t)).norm()});
  }
  RecordProperty("boundary_error_rel", test::sci(worst / size));
  EXPECT_LE(worst, 1e-13 * size);
}

}  // namespace
}  // namespace polarform
