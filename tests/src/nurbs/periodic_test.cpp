// Periodic (closed) B-splines (Bae 2002, eqs. (3.9)-(3.10)) and clipping (§3.3.1): the knot
// vector's closed form, C^{p-1} continuity at the seam, and clip reproducing the curve on [a, b].
#include "src/nurbs/periodic.h"

#include <gtest/gtest.h>

#include "src/error.h"
#include "tests/src/nurbs/kernel_test_support.h"

namespace polarform {
namespace {

TEST(Periodic, KnotVectorClosedForm) {
  EXPECT_EQ(periodic_knots(3, {0, 1, 3, 6}), (Knots{-6, -5, -3, 0, 1, 3, 6, 7, 9, 12}));
  // Fewer spans than the degree: the spacings keep wrapping.
  EXPECT_EQ(periodic_knots(3, {0, 1, 3}), (Knots{-5, -3, -2, 0, 1, 3, 4, 6, 7}));
  EXPECT_THROW(periodic_knots(2, {1.0}), InputError);
  EXPECT_THROW(periodic_knots(2, {0.0, 1.0, 1.0}), InputError);
}

// One period's knots with repeats: the seam knot 0 twice and 3 twice, continued by the period 6;
// simple knots give the breaks' vector.
TEST(Periodic, KnotVectorWithMultipleKnots) {
  EXPECT_EQ(periodic_knots(3, {0, 0, 1, 3, 3}, 6.0),
            (Knots{-5, -3, -3, 0, 0, 1, 3, 3, 6, 6, 7, 9}));
  EXPECT_EQ(periodic_knots(3, {0, 1, 3}, 6.0), periodic_knots(3, {0, 1, 3, 6}));
  EXPECT_THROW(periodic_knots(2, {0.0, 0.0, 0.0, 1.0}, 2.0), InputError);  // 3 > degree
  EXPECT_THROW(periodic_knots(2, {0.0, 2.0}, 2.0), InputError);            // not below the end
  EXPECT_THROW(periodic_knots(2, {1.0, 0.5}, 2.0), InputError);            // decreasing
  EXPECT_THROW(periodic_knots(2, {}, 2.0), InputError);
}

TEST(Periodic, SeamIsCpMinusOne) {
  std::mt19937 rng(51);
  std::uniform_real_distribution<double> gap(0.2, 1.0);
  double worst = 0.0;
  for (int p = 1; p <= 7; ++p) {
    for (int k : {p, p + 3, 12}) {
      std::vector<double> breaks{0.0};
      for (int i = 0; i < k; ++i) breaks.push_back(breaks.back() + gap(rng));
      const BSpline c = periodic_bspline(p, breaks, test::random_coefs(rng, 2, k));
      EXPECT_EQ(c.size(), k + p);
      EXPECT_EQ(c.front(), breaks.front());
      EXPECT_EQ(c.back(), breaks.back());
      const Eigen::MatrixXd d0 = c.derivatives(c.front(), p), d1 = c.derivatives(c.back(), p);
      for (int d = 0; d < p; ++d) {
        const double scale = std::max(1.0, d0.col(d).norm());
        worst = std::max(worst, (d0.col(d) - d1.col(d)).norm() / scale);
      }
    }
  }
  EXPECT_LT(worst, 1e-10);
  RecordProperty("max_relative_seam_jump", test::sci(worst));
}

TEST(Periodic, ClipReproducesTheCurve) {
  std::mt19937 rng(52);
  std::uniform_real_distribution<double> t(0.0, 1.0);
  double worst = 0.0;
  for (int p = 0; p <= 6; ++p) {
    const BSpline periodic =
        periodic_bspline(p, {0.0, 0.4, 1.1, 1.5, 2.2, 3.0, 4.0}, test::random_coefs(rng, 3, 6));
    const BSpline clamped =
        test::random_bspline(rng, p, test::random_knots(rng, p, 0.0, 4.0, 5, p), 3);
    for (const BSpline* c : {&periodic, &clamped}) {
      std::vector<std::pair<double, double>> ranges{{c->front(), c->back()}, {0.4, 2.2}};
      double a = 4.0 * t(rng), b = 4.0 * t(rng);
      if (a > b) std::swap(a, b);
      ranges.emplace_back(a, b);
      for (auto [lo, hi] : ranges) {
        const BSpline k = clip(*c, lo, hi);
        EXPECT_EQ(k.front(), lo);
        EXPECT_EQ(k.back(), hi);
        EXPECT_EQ(multiplicity(k.knots(), lo), p + 1);
        EXPECT_EQ(multiplicity(k.knots(), hi), p + 1);
        for (int i = 0; i <= 400; ++i) {
          const double u = lo + (hi - lo) * i / 400.0;
          if (p == 0 && i == 400) continue;  // a step function's value at its end is one-sided
          worst = std::max(worst, (k.point(u) - c->point(u)).norm());
        }
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_deviation", test::sci(worst));
}

TEST(Periodic, ClipSurfaceAndBadInput) {
  std::mt19937 rng(53);
  const BSpline ring = periodic_bspline(3, {0, 1, 2, 3, 4, 5}, test::random_coefs(rng, 2, 5));
  // A surface closed in v: each u-row a periodic curve.
  const Knots V = ring.knots(), U{0, 0, 1, 1};
  const BSplineSurface s(1, 3, U, V, test::random_coefs(rng, 1, 2 * 8));
  const BSplineSurface c = clip_v(s, 0.0, 5.0);
  EXPECT_EQ(c.knots_v(), (Knots{0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5}));
  EXPECT_LT(test::max_deviation(c, s, 50), 1e-12);
  const BSplineSurface cu = clip_u(s, 0.25, 0.75);
  EXPECT_LT((cu.point(0.25, 2.5) - s.point(0.25, 2.5)).norm(), 1e-14);
  EXPECT_THROW(clip(ring, 1.0, 1.0), InputError);
  EXPECT_THROW(clip(ring, -0.5, 1.0), InputError);
  EXPECT_THROW(periodic_bspline(3, {0, 1, 2}, test::random_coefs(rng, 2, 3)), InputError);
}

}  // namespace
}  // namespace polarform
