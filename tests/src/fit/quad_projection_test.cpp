// Projection onto a blanket's quads (spec P6): every point parametrised, approximate parameters
// near the foot, polished parameters equal to the global projection, points outside every quad
// near a curved boundary, search cost against brute force, and the full cylinder.
#include "src/fit/quad_projection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "src/error.h"
#include "src/nurbs/point_inversion.h"
#include "tests/src/fit/fit_test_support.h"
#include "tests/src/fit/patch_test_support.h"

namespace polarform {
namespace {

// A doubly curved bicubic patch whose v = 0 boundary bulges outwards in its plane, so that the
// blanket's chords cut inside it.
NurbsSurface curved_patch() {
  const int n = 6;
  NurbsSurface::Points P(n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = 2.0 * i,
                   y = 2.0 * j - (j == 0 ? 3.0 * std::sin(std::numbers::pi * i / (n - 1)) : 0.0);
      P[i * n + j] = Eigen::Vector3d(x, y, 0.15 * (x - 5) * (x - 5) - 0.1 * (y - 5) * (y - 5));
    }
  const Knots K = uniform_clamped_knots(3, n - 3, 0.0, 1.0);
  return NurbsSurface(3, 3, K, K, P);
}

double net_diagonal(const NurbsSurface& s) {
  Eigen::Vector3d lo = s.control_point(0, 0), hi = lo;
  for (int i = 0; i < s.size_u(); ++i)
    for (int j = 0; j < s.size_v(); ++j) {
      lo = lo.cwiseMin(s.control_point(i, j));
      hi = hi.cwiseMax(s.control_point(i, j));
    }
  return (hi - lo).norm();
}

// Points on the surface moved along the normal by up to ±offset, plus `edge` points at v ≈ 0.
Eigen::Matrix3Xd points_near(const NurbsSurface& s, int n, int edge, double offset, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0), E(0.0, 0.01), O(-offset, offset);
  Eigen::Matrix3Xd p(3, n + edge);
  for (int k = 0; k < n + edge; ++k) {
    const double u = U(rng), v = k < n ? U(rng) : E(rng);
    p.col(k) = s.point(u, v) + O(rng) * s.normal(u, v);
  }
  return p;
}

// P6.1–P6.3 on the curved patch: 11 517 points (300 of them next to the bulging boundary) on a
// 40 × 30 vertex blanket (1131 quads).
TEST(QuadProjection, ParametrisesEveryPointAndPolishesToTheFoot) {
  const NurbsSurface s = curved_patch();
  const double diag = net_diagonal(s);
  const Eigen::Matrix3Xd pts = points_near(s, 11217, 300, 0.01 * diag, 5);
  const SurfaceBlanket b = test::uniform_blanket(s, 40, 30);
  ASSERT_GE(b.quads(), 1000);
  const PatchParameters r = parametrize_on_blanket(pts, s, b);
  const SurfaceProjector projector(s);
  double worst_param = 0.0;
  for (Eigen::Index k = 0; k < pts.cols(); ++k) {
    ASSERT_TRUE(std::isfinite(r.u[k]) && std::isfinite(r.v[k])) << k;  // P6.1
    const SurfaceProjection g = projector.project(pts.col(k));
    worst_param = std::max({worst_param, std::abs(r.u[k] - g.u), std::abs(r.v[k] - g.v)});
    EXPECT_NEAR(r.distance[k], g.distance, 1e-12 * diag);
  }
  EXPECT_LE(worst_param, 1e-12);         // P6.2, polished
  EXPECT_GT(r.stats.clamped_points, 0);  // the boundary points outside every quad
  const double share = static_cast<double>(r.stats.point_quad_tests) / r.stats.brute_force_tests;
  EXPECT_LE(share, 0.05);  // P6.3
  EXPECT_EQ(r.stats.brute_force_tests, static_cast<long long>(b.quads()) * pts.cols());
  EXPECT_TRUE(r.stats.polished);
  RecordProperty("polished_param_error", test::sci(worst_param));
  RecordProperty("tests_share", test::sci(share));
  RecordProperty("clamped_points", r.stats.clamped_points);
  RecordProperty("cells", r.stats.cells);
}

// The largest distance between the blanket's bilinear quads and the surface (3 × 3 samples a quad).
double blanket_deviation(const NurbsSurface& s, const SurfaceBlanket& b) {
  double worst = 0.0;
  const auto P = [&](int a, int c) { return Eigen::Vector3d(b.points.col(b.vertex(a, c))); };
  for (int a = 0; a < b.quads_u(); ++a)
    for (int c = 0; c < b.quads_v(); ++c)
      for (double x : {0.25, 0.5, 0.75})
        for (double y : {0.25, 0.5, 0.75}) {
          const Eigen::Vector3d q = (1 - x) * (1 - y) * P(a, c) + x * (1 - y) * P(a + 1, c) +
                                    x * y * P(a + 1, c + 1) + (1 - x) * y * P(a, c + 1);
          const double u = b.u[a] + x * (b.u[a + 1] - b.u[a]),
                       v = b.v[c] + y * (b.v[c + 1] - b.v[c]);
          worst = std::max(worst, (s.point(u, v) - q).norm());
        }
  return worst;
}

// P6.2, approximate: on a coarse blanket (quads within 0.5 %·diag of the surface) the quad
// parameters lie within 0.5 %·diag (surface position) of the exact foot, the clamped boundary
// points included; the plane search agrees.
TEST(QuadProjection, ApproximateParametersNearTheFoot) {
  const NurbsSurface s = curved_patch();
  const double diag = net_diagonal(s);
  const Eigen::Matrix3Xd pts = points_near(s, 3000, 300, 0.005 * diag, 6);
  const SurfaceBlanket b = test::uniform_blanket(s, 22, 22);
  ASSERT_LE(blanket_deviation(s, b), 0.005 * diag);
  const SurfaceProjector projector(s);
  for (PatchSearch search : {PatchSearch::grid3d, PatchSearch::plane}) {
    const PatchParameters r = parametrize_on_blanket(pts, s, b, {search, false, 2});
    EXPECT_FALSE(r.stats.polished);
    EXPECT_GT(r.stats.clamped_points, 0);
    double worst = 0.0, worst_clamped = 0.0;
    for (Eigen::Index k = 0; k < pts.cols(); ++k) {
      const SurfaceProjection g = projector.project(pts.col(k));
      const double d = (s.point(r.u[k], r.v[k]) - g.point).norm();
      worst = std::max(worst, d);
      if (r.clamped[k]) worst_clamped = std::max(worst_clamped, d);
    }
    EXPECT_LE(worst, 0.005 * diag);
    RecordProperty(search == PatchSearch::grid3d ? "grid3d_worst_rel" : "plane_worst_rel",
                   test::sci(worst / diag));
    RecordProperty(
        search == PatchSearch::grid3d ? "grid3d_clamped_worst_rel" : "plane_clamped_worst_rel",
        test::sci(worst_clamped / diag));
  }
}

// P6.4: a full (closed) cylinder: the plane search refuses (folds), grid3d parametrises every
// point, polished to the global foot.
TEST(QuadProjection, FullCylinderNeedsGrid3d) {
  const NurbsSurface s = test::cylinder_patch(360.0, 10.0, 8.0, 16);
  const double diag = net_diagonal(s);
  const Eigen::Matrix3Xd pts = points_near(s, 4000, 0, 0.003 * diag, 7);
  const SurfaceBlanket b = test::uniform_blanket(s, 90, 6);
  ASSERT_LE(blanket_deviation(s, b), 0.005 * diag);
  try {
    parametrize_on_blanket(pts, s, b, {PatchSearch::plane, true, 2});
    ADD_FAILURE() << "the plane search accepted a closed cylinder";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("grid3d"), std::string::npos) << e.what();
  }
  const PatchParameters r = parametrize_on_blanket(pts, s, b);
  const PatchParameters approx = parametrize_on_blanket(pts, s, b, {PatchSearch::grid3d, false, 2});
  const SurfaceProjector projector(s);
  double worst_distance = 0.0, worst_approx = 0.0;
  for (Eigen::Index k = 0; k < pts.cols(); ++k) {
    const SurfaceProjection g = projector.project(pts.col(k));
    worst_distance = std::max(worst_distance, std::abs(r.distance[k] - g.distance));
    worst_approx = std::max(worst_approx, (s.point(approx.u[k], approx.v[k]) - g.point).norm());
  }
  EXPECT_LE(worst_distance, 1e-12 * diag);
  EXPECT_LE(worst_approx, 0.005 * diag);
  RecordProperty("cylinder_approx_worst_rel", test::sci(worst_approx / diag));
}

// P5.3 through P6: a 250° patch folds over its max-area plane, so the plane search refuses it
// (naming the folds), while a 180° patch is accepted and agrees with grid3d.
TEST(QuadProjection, PlaneSearchRefuses250DegreesAndAccepts180) {
  const NurbsSurface s250 = test::cylinder_patch(250.0, 10.0, 8.0, 12);
  const Eigen::Matrix3Xd p250 = points_near(s250, 2000, 0, 0.01, 8);
  const SurfaceBlanket b250 = test::uniform_blanket(s250, 60, 6);
  EXPECT_THROW(parametrize_on_blanket(p250, s250, b250, {PatchSearch::plane, true, 2}), InputError);
  const PatchParameters g250 = parametrize_on_blanket(p250, s250, b250);
  EXPECT_LE(g250.distance.maxCoeff(), 0.01 + 1e-9);

  const NurbsSurface s180 = test::cylinder_patch(180.0, 10.0, 8.0, 10);
  const Eigen::Matrix3Xd p180 = points_near(s180, 2000, 0, 0.01, 9);
  const SurfaceBlanket b180 = test::uniform_blanket(s180, 50, 6);
  const PatchParameters plane =
      parametrize_on_blanket(p180, s180, b180, {PatchSearch::plane, true, 2});
  const PatchParameters grid = parametrize_on_blanket(p180, s180, b180);
  EXPECT_EQ(plane.stats.folded_triangles, 0);
  EXPECT_LE((plane.u - grid.u).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LE((plane.v - grid.v).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(QuadProjection, RejectsABadBlanket) {
  const NurbsSurface s = curved_patch();
  SurfaceBlanket b = test::uniform_blanket(s, 4, 4);
  b.v.pop_back();
  EXPECT_THROW(parametrize_on_blanket(Eigen::Matrix3Xd::Zero(3, 2), s, b), InputError);
}

}  // namespace
}  // namespace polarform
