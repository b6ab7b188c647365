// fit_bicubic_coons (Piegl & Tiller 2001, §2.2; spec P2 checks 2–4): cross derivatives fitted from
// 30 % of 10^4 exact-parameter samples reproduce a bicubic patch (written with interior knots, so
// the derivative curves have free control points) to 1e-10·diag with the twists compatible to
// 1e-12; on a patch with a lifted interior the bicubic base is closer to the cloud than the
// bilinear one.
#include "src/fit/bicubic_coons_fit.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "src/error.h"
#include "src/nurbs/knot_refinement.h"
#include "tests/support/src/patch_test_support.h"

namespace polarform {
namespace {

using Eigen::Vector3d;

std::string sci(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

struct Samples {
  Eigen::Matrix3Xd points;
  Eigen::VectorXd u, v;
};

// n samples at uniform random (u, v); the first `share` of them form the fitting subset.
Samples sample(const NurbsSurface& s, int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> t(0.0, 1.0);
  Samples out{Eigen::Matrix3Xd(3, n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (int k = 0; k < n; ++k) {
    out.u(k) = t(rng);
    out.v(k) = t(rng);
    out.points.col(k) = s.point(out.u(k), out.v(k));
  }
  return out;
}

Samples head(const Samples& s, int n) { return {s.points.leftCols(n), s.u.head(n), s.v.head(n)}; }

double max_distance(const NurbsSurface& s, const Samples& cloud) {
  double worst = 0.0;
  for (Eigen::Index k = 0; k < cloud.points.cols(); ++k)
    worst = std::max(worst, (s.point(cloud.u(k), cloud.v(k)) - cloud.points.col(k)).norm());
  return worst;
}

NurbsSurface refined_random_patch(std::mt19937& rng) {
  std::uniform_real_distribution<double> c(-1.5, 1.5);
  NurbsSurface::Points P;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      P.push_back(Vector3d(10.0 * i / 3 + c(rng), 8.0 * j / 3 + c(rng), c(rng)));
  const NurbsSurface bez = test::bezier_patch(P);
  return NurbsSurface(
      refine_knots_v(refine_knots_u(bez.homogeneous(), {0.25, 0.5, 0.8}), {0.4, 0.7}));
}

TEST(BicubicCoonsFit, ReproducesBicubicPatchFromThirtyPercent) {
  std::mt19937 rng(2001);
  const NurbsSurface s = refined_random_patch(rng);
  const Samples all = sample(s, 10000, rng);
  const BicubicCoonsFit fit = fit_bicubic_coons(test::surface_boundary(s), head(all, 3000).points,
                                                head(all, 3000).u, head(all, 3000).v);
  const double diag = test::net_diagonal(s);
  double worst = 0.0;
  for (int i = 0; i <= 100; ++i)
    for (int j = 0; j <= 100; ++j)
      worst = std::max(
          worst, (fit.surface.point(i / 100.0, j / 100.0) - s.point(i / 100.0, j / 100.0)).norm());
  RecordProperty("reproduction_rel", sci(worst / diag));
  RecordProperty("twist_mismatch", sci(fit.twist_mismatch));
  EXPECT_LE(worst, 1e-10 * diag);
  EXPECT_LE(fit.twist_mismatch, 1e-12);  // mm, twists here are O(10) mm
  // The fitted derivative curves are the exact ones.
  const CrossDerivatives exact = test::surface_cross_derivatives(s);
  for (int k = 0; k <= 100; ++k)
    EXPECT_LE((fit.derivatives.du0.point(k / 100.0) - exact.du0.point(k / 100.0)).norm(),
              1e-9 * diag);
}

// Nearly straight boundaries, the four interior control points lifted by 0.3·diag (spec S8(d)).
TEST(BicubicCoonsFit, BeatsBilinearOnALiftedInterior) {
  NurbsSurface::Points P;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const bool inner = i > 0 && i < 3 && j > 0 && j < 3;
      P.push_back(Vector3d(10.0 * i / 3, 10.0 * j / 3, 0.1 * std::sin(i + 2.0 * j)));
      if (inner) P.back().z() += 0.3 * std::sqrt(200.0);
    }
  const NurbsSurface s(
      refine_knots_v(refine_knots_u(test::bezier_patch(P).homogeneous(), {0.3, 0.6}), {0.5}));
  std::mt19937 rng(4);
  const Samples all = sample(s, 10000, rng);
  const PatchBoundary b = test::surface_boundary(s);
  const double bilinear = max_distance(bilinear_coons(b), all);
  const Samples sub = head(all, 3000);
  const double bicubic = max_distance(fit_bicubic_coons(b, sub.points, sub.u, sub.v).surface, all);
  const double scaled = max_distance(
      fit_bicubic_coons(b, sub.points, sub.u, sub.v, {.scale_cross_derivatives = true}).surface,
      all);
  RecordProperty("bilinear_max", sci(bilinear));
  RecordProperty("bicubic_max", sci(bicubic));
  RecordProperty("bicubic_scaled_max", sci(scaled));
  EXPECT_LT(bicubic, bilinear);
}

// A bump no Coons patch of the boundaries can represent: a 7 × 7 cubic net over a flat square with
// its central 3 × 3 control points lifted (boundaries straight, cross derivatives zero at the
// edges).
TEST(BicubicCoonsFit, BeatsBilinearOnAnInteriorBump) {
  NurbsSurface::Points P;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      P.push_back(Vector3d(i * 10.0 / 6, j * 10.0 / 6,
                           std::abs(i - 3) <= 1 && std::abs(j - 3) <= 1 ? 3.0 : 0.0));
  const Knots U{0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1};
  const NurbsSurface s(3, 3, U, U, P);
  std::mt19937 rng(6);
  const Samples all = sample(s, 10000, rng);
  const PatchBoundary b = test::surface_boundary(s);
  const Samples sub = head(all, 3000);
  const double bilinear = max_distance(bilinear_coons(b), all);
  const double bicubic = max_distance(fit_bicubic_coons(b, sub.points, sub.u, sub.v).surface, all);
  const double scaled = max_distance(
      fit_bicubic_coons(b, sub.points, sub.u, sub.v, {.scale_cross_derivatives = true}).surface,
      all);
  RecordProperty("bilinear_max", sci(bilinear));
  RecordProperty("bicubic_max", sci(bicubic));
  RecordProperty("bicubic_scaled_max", sci(scaled));
  EXPECT_LT(bicubic, bilinear);
}

TEST(BicubicCoonsFit, RefusesTooFewPoints) {
  std::mt19937 rng(5);
  const NurbsSurface s = refined_random_patch(rng);
  const Samples few = sample(s, 3, rng);
  EXPECT_THAT([&] { fit_bicubic_coons(test::surface_boundary(s), few.points, few.u, few.v); },
              testing::ThrowsMessage<InputError>(testing::HasSubstr("3 points for")));
}

}  // namespace
}  // namespace polarform
