// decompose_surface (Piegl & Tiller 2001, §3.1; spec P4): the blanket is the full tensor grid
// (exact counts, every interior vertex in 4 quads, vertices on the surface); over 50 × 50 samples
// per quad the surface stays within 2ε of its quad (measured against the quad's two triangles
// 00-10-11 and 00-11-01), also for a planar patch with curved edges; on a thin, strongly curved
// strip at 0.1 % the curvature rule needs at most half the quads of the extent rule; a patch with a
// collapsed edge completes; the guards throw.
#include "src/nurbs/surface_decomposition.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/error.h"
#include "tests/src/nurbs/kernel_test_support.h"
#include "tests/support/src/patch_test_support.h"

namespace polarform {
namespace {

using Eigen::Vector3d;

// Closest point of segment ab to p (Ericson 2005, §5.1.2), a = b allowed.
double segment_distance(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
  const Vector3d d = b - a;
  const double dd = d.squaredNorm();
  const double t = dd > 0.0 ? std::clamp((p - a).dot(d) / dd, 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

// Distance from p to triangle abc: the plane foot when it lies inside, else the nearest edge
// (Ericson 2005, §5.1.5 by regions); a degenerate triangle is its edges.
double triangle_distance(const Vector3d& p, const Vector3d& a, const Vector3d& b,
                         const Vector3d& c) {
  const Vector3d n = (b - a).cross(c - a);
  const double edges =
      std::min({segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, c, a)});
  if (!(n.norm() > 1e-14 * (b - a).norm() * (c - a).norm())) return edges;
  const Vector3d f = p - n.dot(p - a) / n.squaredNorm() * n;
  const bool inside = (b - a).cross(f - a).dot(n) >= 0 && (c - b).cross(f - b).dot(n) >= 0 &&
                      (a - c).cross(f - c).dot(n) >= 0;
  return inside ? (p - f).norm() : edges;
}

// Spec P4 check 1: the counts of the tensor grid and its vertices on the surface.
void expect_crack_free(const NurbsSurface& s, const SurfaceDecomposition& d) {
  const SurfaceBlanket& b = d.blanket;
  const int nu = static_cast<int>(b.u.size()), nv = static_cast<int>(b.v.size());
  EXPECT_EQ(b.points.cols(), nu * nv);
  EXPECT_EQ(b.quads(), (nu - 1) * (nv - 1));
  EXPECT_EQ(b.u.front(), s.front_u());
  EXPECT_EQ(b.u.back(), s.back_u());
  EXPECT_EQ(b.v.front(), s.front_v());
  EXPECT_EQ(b.v.back(), s.back_v());
  EXPECT_TRUE(std::is_sorted(b.u.begin(), b.u.end()) &&
              std::adjacent_find(b.u.begin(), b.u.end()) == b.u.end());
  EXPECT_TRUE(std::is_sorted(b.v.begin(), b.v.end()) &&
              std::adjacent_find(b.v.begin(), b.v.end()) == b.v.end());
  std::vector<int> uses(b.points.cols(), 0);
  for (int a = 0; a < b.quads_u(); ++a)
    for (int c = 0; c < b.quads_v(); ++c)
      for (int k : {b.vertex(a, c), b.vertex(a + 1, c), b.vertex(a, c + 1), b.vertex(a + 1, c + 1)})
        ++uses[k];
  for (int a = 1; a + 1 < nu; ++a)
    for (int c = 1; c + 1 < nv; ++c) EXPECT_EQ(uses[b.vertex(a, c)], 4);
  double off = 0.0;
  for (int a = 0; a < nu; ++a)
    for (int c = 0; c < nv; ++c)
      off = std::max(off, (b.points.col(b.vertex(a, c)) - s.point(b.u[a], b.v[c])).norm());
  EXPECT_EQ(off, 0.0);
}

// Spec P4 check 2: max over quads and 50 × 50 samples of the distance to the quad's triangles.
double max_quad_distance(const NurbsSurface& s, const SurfaceBlanket& b) {
  double worst = 0.0;
  for (int a = 0; a < b.quads_u(); ++a)
    for (int c = 0; c < b.quads_v(); ++c) {
      const Vector3d p00 = b.points.col(b.vertex(a, c)), p10 = b.points.col(b.vertex(a + 1, c)),
                     p01 = b.points.col(b.vertex(a, c + 1)),
                     p11 = b.points.col(b.vertex(a + 1, c + 1));
      for (int i = 0; i < 50; ++i)
        for (int j = 0; j < 50; ++j) {
          const Vector3d q = s.point(b.u[a] + (b.u[a + 1] - b.u[a]) * i / 49.0,
                                     b.v[c] + (b.v[c + 1] - b.v[c]) * j / 49.0);
          worst = std::max(worst, std::min(triangle_distance(q, p00, p10, p11),
                                           triangle_distance(q, p00, p11, p01)));
        }
    }
  return worst;
}

// A doubly curved bicubic patch (spec S8(a)-like: a bulge, curved both ways).
NurbsSurface bulged_patch() {
  NurbsSurface::Points P;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      P.push_back(
          Vector3d(10.0 * i / 3, 10.0 * j / 3,
                   4.0 * std::sin(std::numbers::pi * i / 3) * std::sin(std::numbers::pi * j / 3) +
                       0.5 * i * j / 9.0));
  return test::bezier_patch(P);
}

// Spec S8(b): u along an axis of length 100, v a 120° arc of radius 10 (one cubic Bezier, handle
// length (4/3)·tan(30°)·r).
NurbsSurface thin_curved_strip() {
  const double r = 10.0, h = 4.0 / 3.0 * std::tan(std::numbers::pi / 6) * r;
  const double a0 = -std::numbers::pi / 3, a1 = std::numbers::pi / 3;
  const Vector3d e0(0, std::cos(a0), std::sin(a0)), e1(0, std::cos(a1), std::sin(a1));
  const Vector3d t0(0, -std::sin(a0), std::cos(a0)), t1(0, -std::sin(a1), std::cos(a1));
  const Vector3d arc[4] = {r * e0, r * e0 + h * t0, r * e1 - h * t1, r * e1};
  NurbsSurface::Points P;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) P.push_back(arc[j] + Vector3d(100.0 * i / 3, 0, 0));
  return test::bezier_patch(P);
}

TEST(SurfaceDecomposition, CrackFreeAndWithinTwoEpsilon) {
  const NurbsSurface s = bulged_patch();
  for (SplitRule rule : {SplitRule::extent, SplitRule::curvature}) {
    const SurfaceDecomposition d = decompose_surface(s, {.tolerance_rel = 0.005, .split = rule});
    EXPECT_NEAR(d.tolerance, 0.005 * test::net_diagonal(s), 1e-15);
    expect_crack_free(s, d);
    const double worst = max_quad_distance(s, d.blanket);
    const std::string name = rule == SplitRule::extent ? "extent" : "curvature";
    RecordProperty(name + "_quads", d.blanket.quads());
    RecordProperty(name + "_max_over_eps", test::sci(worst / d.tolerance));
    EXPECT_GT(d.blanket.quads(), 1);
    EXPECT_LE(worst, 2 * d.tolerance);
  }
}

TEST(SurfaceDecomposition, CurvatureRuleHalvesTheQuadsOfAThinCurvedStrip) {
  const NurbsSurface s = thin_curved_strip();
  const SurfaceDecomposition extent = decompose_surface(s, {.tolerance_rel = 0.001});
  const SurfaceDecomposition curvature =
      decompose_surface(s, {.tolerance_rel = 0.001, .split = SplitRule::curvature});
  expect_crack_free(s, extent);
  expect_crack_free(s, curvature);
  const double e_extent = max_quad_distance(s, extent.blanket);
  const double e_curvature = max_quad_distance(s, curvature.blanket);
  RecordProperty("extent_quads", extent.blanket.quads());
  RecordProperty("curvature_quads", curvature.blanket.quads());
  RecordProperty("extent_grid", std::to_string(extent.blanket.quads_u()) + "x" +
                                    std::to_string(extent.blanket.quads_v()));
  RecordProperty("curvature_grid", std::to_string(curvature.blanket.quads_u()) + "x" +
                                       std::to_string(curvature.blanket.quads_v()));
  RecordProperty("extent_max_over_eps", test::sci(e_extent / extent.tolerance));
  RecordProperty("curvature_max_over_eps", test::sci(e_curvature / curvature.tolerance));
  EXPECT_LE(2 * curvature.blanket.quads(), extent.blanket.quads());
  EXPECT_LE(e_extent, 2 * extent.tolerance);
  EXPECT_LE(e_curvature, 2 * curvature.tolerance);
}

// Spec S8(e): the boundary u = 0 collapsed to one point.
TEST(SurfaceDecomposition, CollapsedEdgeCompletes) {
  NurbsSurface::Points P;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      P.push_back(i == 0 ? Vector3d(0, 5, 1)
                         : Vector3d(10.0 * i / 3, 10.0 * j / 3 * i / 3 + 5 * (1 - i / 3.0),
                                    3.0 * std::sin(i + j)));
  const NurbsSurface s = test::bezier_patch(P);
  for (SplitRule rule : {SplitRule::extent, SplitRule::curvature}) {
    const SurfaceDecomposition d = decompose_surface(s, {.tolerance_rel = 0.005, .split = rule});
    expect_crack_free(s, d);
    const double worst = max_quad_distance(s, d.blanket);
    RecordProperty(std::string(rule == SplitRule::extent ? "extent" : "curvature") + "_quads",
                   d.blanket.quads());
    EXPECT_LE(worst, 2 * d.tolerance);
  }
}

// Two adjacent edges collapsed: the corners' diagonals d1 × d2 vanish, the LSQ plane decides.
TEST(SurfaceDecomposition, DegenerateCornerNormalFallsBackToTheLeastSquaresPlane) {
  NurbsSurface::Points P;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      P.push_back(i == 0 || j == 0 ? Vector3d(0, 0, 0)
                                   : Vector3d(3.0 * i + 0.5 * j, 3.0 * j + 0.5 * i, 0.2 * i * j));
  const NurbsSurface s = test::bezier_patch(P);
  const SurfaceDecomposition d = decompose_surface(s, {.tolerance_rel = 0.01});
  expect_crack_free(s, d);
  EXPECT_LE(max_quad_distance(s, d.blanket), 2 * d.tolerance);
}

// A planar patch with curved edges passes the mid-plane test at once; the bilinear test splits it.
TEST(SurfaceDecomposition, PlanarPatchWithCurvedEdgesIsSplit) {
  NurbsSurface::Points P;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      P.push_back(Vector3d(10.0 * i / 3 + 2.0 * std::sin(std::numbers::pi * j / 3),
                           10.0 * j / 3 + 2.0 * std::sin(std::numbers::pi * i / 3), 0.0));
  const NurbsSurface s = test::bezier_patch(P);
  const SurfaceDecomposition d = decompose_surface(s, {.tolerance_rel = 0.005});
  expect_crack_free(s, d);
  EXPECT_GT(d.blanket.quads(), 1);
  EXPECT_LE(max_quad_distance(s, d.blanket), 2 * d.tolerance);
}

TEST(SurfaceDecomposition, GuardsThrow) {
  const NurbsSurface s = bulged_patch();
  EXPECT_THAT([&] { decompose_surface(s, {.tolerance_rel = 0.0}); },
              testing::ThrowsMessage<InputError>(testing::HasSubstr("tolerance_rel")));
  EXPECT_THAT([&] { decompose_surface(s, {.tolerance_rel = 1e-300}); },
              testing::ThrowsMessage<NumericalError>(testing::HasSubstr("splits")));
}

}  // namespace
}  // namespace polarform
