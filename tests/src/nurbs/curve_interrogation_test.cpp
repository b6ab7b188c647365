// Curve interrogation against closed forms and independent sampling: derivative jumps at knots,
// the curvature of a rational circle, inflections of polynomial and rational cubics.
#include "src/nurbs/curve_interrogation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/error.h"

namespace polarform {
namespace {

using Points = NurbsCurve2d::Points;

// A uniform cubic with simple knots is C²: the first two derivatives do not jump; the third, a
// constant per span, jumps by the difference of the neighbouring spans' values.
TEST(CurveInterrogation, DerivativeJumpsAtSimpleAndDoubleKnots) {
  const NurbsCurve2d c(3, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3},
                       Points{{0, 0}, {1, 2}, {2, -1}, {3, 3}, {4, 0}, {5, 1}});
  for (int k : {1, 2}) {
    const std::vector<KnotJump> jumps = derivative_jumps(c, k);
    ASSERT_EQ(jumps.size(), 2u);
    for (const KnotJump& j : jumps) EXPECT_LT(j.jump, 1e-11) << k;
  }
  const std::vector<KnotJump> third = derivative_jumps(c, 3);
  ASSERT_EQ(third.size(), 2u);
  for (const KnotJump& j : third) {
    const Eigen::Vector2d left = c.derivatives(j.u - 0.5, 3)[3],
                          right = c.derivatives(j.u + 0.5, 3)[3];
    EXPECT_NEAR(j.jump, (right - left).norm(), 1e-9) << j.u;
    EXPECT_GT(j.jump, 1.0);
  }
  // A double knot leaves the curve C¹: the second derivative jumps, measured against one-sided
  // finite differences.
  const NurbsCurve2d d(3, {0, 0, 0, 0, 1, 1, 2, 2, 2, 2},
                       Points{{0, 0}, {1, 2}, {2, -1}, {3, 3}, {4, 0}, {5, 1}});
  const std::vector<KnotJump> second = derivative_jumps(d, 2);
  ASSERT_EQ(second.size(), 1u);
  const double e = 1e-7;
  const Eigen::Vector2d left = d.derivatives(1 - e, 2)[2], right = d.derivatives(1 + e, 2)[2];
  EXPECT_NEAR(second[0].jump, (right - left).norm(), 1e-4);
  EXPECT_GT(second[0].jump, 1.0);
  EXPECT_THROW(derivative_jumps(d, 4), InputError);
}

// One cubic B-spline basis function on uniform knots of spacing h, as the y of a curve with
// x = t: its third derivative jumps by (1, −4, 6, −4, 1)/h³ at its five knots (spec M2, check 1).
TEST(CurveInterrogation, BasisFunctionJumpsAreTheBinomialPattern) {
  const double h = 0.5;
  Knots knots;
  for (int i = 0; i <= 12; ++i) knots.push_back(h * i);
  // Control points: x linear in t (no jumps), y the basis function N_4 (a single 1).
  Points points;
  for (int i = 0; i < 9; ++i) points.push_back({h * (i + 1), i == 4 ? 1.0 : 0.0});
  const NurbsCurve2d c(3, knots, points);
  const std::vector<KnotJump> jumps = derivative_jumps(c, 3);
  const double pattern[] = {1, -4, 6, -4, 1};
  for (int k = 0; k < 5; ++k) {
    const double u = h * (4 + k);  // the support [4h, 8h] of N_4 between knots 4h … 8h
    const auto it = std::find_if(jumps.begin(), jumps.end(),
                                 [&](const KnotJump& j) { return std::abs(j.u - u) < 1e-12; });
    ASSERT_NE(it, jumps.end()) << u;
    EXPECT_NEAR(it->jump, std::abs(pattern[k]) / (h * h * h), 1e-12 / (h * h * h)) << u;
  }
}

// A quarter circle of radius 5 as a rational quadratic: κ = 1/5 everywhere, counter-clockwise.
TEST(CurveInterrogation, CurvatureOfARationalCircleIsOneOverItsRadius) {
  const NurbsCurve2d arc(2, {0, 0, 0, 1, 1, 1}, Points{{5, 0}, {5, 5}, {0, 5}},
                         {1, std::sqrt(0.5), 1});
  for (double u = 0; u <= 1; u += 0.125) EXPECT_NEAR(signed_curvature(arc, u), 0.2, 1e-13) << u;
  EXPECT_TRUE(inflections(arc).empty());
}

// dκ/du against central differences of κ on a rational cubic (away from its knots).
TEST(CurveInterrogation, CurvatureDerivativeIsTheSlopeOfTheCurvature) {
  const NurbsCurve2d r(3, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3},
                       Points{{0, 0}, {1, 2}, {2, -1}, {3, 3}, {4, 0}, {5, 1}},
                       {1, 2, 0.5, 1.5, 0.8, 1});
  const double h = 1e-5;
  for (double u : {0.3, 0.7, 1.4, 1.9, 2.5}) {
    const double fd = (signed_curvature(r, u + h) - signed_curvature(r, u - h)) / (2 * h);
    EXPECT_NEAR(curvature_derivative(r, u), fd, 1e-5 * std::max(1.0, std::abs(fd))) << u;
  }
}

// Independent check: sign changes of the sampled curvature, bisected.
std::vector<double> sampled_inflections(const NurbsCurve2d& c) {
  std::vector<double> out;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    double a = c.front() + (c.back() - c.front()) * i / n;
    double b = c.front() + (c.back() - c.front()) * (i + 1) / n;
    if (signed_curvature(c, a) * signed_curvature(c, b) >= 0) continue;
    for (int k = 0; k < 100; ++k) {
      const double m = 0.5 * (a + b);
      ((signed_curvature(c, m) > 0) == (signed_curvature(c, a) > 0) ? a : b) = m;
    }
    out.push_back(0.5 * (a + b));
  }
  return out;
}

TEST(CurveInterrogation, InflectionsOfPolynomialAndRationalCurves) {
  // The symmetric S of a cubic Bézier inflects at its middle.
  const NurbsCurve2d s(3, {0, 0, 0, 0, 1, 1, 1, 1}, Points{{0, 0}, {1, 1}, {2, -1}, {3, 0}});
  const std::vector<double> mid = inflections(s);
  ASSERT_EQ(mid.size(), 1u);
  EXPECT_NEAR(mid[0], 0.5, 1e-12);
  // A rational cubic B-spline with several turns: the same inflections as the sampled curvature.
  const NurbsCurve2d r(3, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3},
                       Points{{0, 0}, {1, 2}, {2, -1}, {3, 3}, {4, 0}, {5, 1}},
                       {1, 2, 0.5, 1.5, 0.8, 1});
  const std::vector<double> found = inflections(r), expected = sampled_inflections(r);
  ASSERT_EQ(found.size(), expected.size());
  ASSERT_GE(found.size(), 3u);
  for (std::size_t i = 0; i < found.size(); ++i) EXPECT_NEAR(found[i], expected[i], 1e-9) << i;
}

}  // namespace
}  // namespace polarform
