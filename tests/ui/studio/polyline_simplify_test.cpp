// Polyline simplification: the output is a subsequence of the input with both endpoints, and every
// dropped point lies within the tolerance of the output chord that replaces it (measured here);
// straight runs collapse to their ends, and fewer points come out of smooth curves.
#include "ui/studio/polyline_simplify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace polarform::studio {
namespace {

double distance_to_segment(const PixelPoint& p, const PixelPoint& a, const PixelPoint& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  const double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0;
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

// The largest distance of an input point from the output chord spanning it; fails the test when
// the output is not a subsequence of the input keeping both endpoints.
double measured_deviation(const Polyline& in, const Polyline& out) {
  EXPECT_GE(out.size(), std::min<std::size_t>(in.size(), 2));
  EXPECT_EQ(out.front(), in.front());
  EXPECT_EQ(out.back(), in.back());
  std::vector<std::size_t> at;  // index in `in` of each output point; the last is the last
  std::size_t next = 0;
  for (std::size_t k = 0; k + 1 < out.size(); ++k) {
    while (next < in.size() && !(in[next] == out[k])) ++next;
    EXPECT_LT(next, in.size()) << "an output point is not an input point in order";
    if (next == in.size()) return INFINITY;
    at.push_back(next++);
  }
  at.push_back(in.size() - 1);
  double worst = 0.0;
  for (std::size_t k = 0; k + 1 < at.size(); ++k)
    for (std::size_t i = at[k]; i <= at[k + 1]; ++i)
      worst = std::max(worst, distance_to_segment(in[i], in[at[k]], in[at[k + 1]]));
  return worst;
}

Polyline sine_curve(int n, double amplitude, double noise, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-noise, noise);
  Polyline p;
  for (int i = 0; i < n; ++i) {
    const double x = 1000.0 * i / (n - 1);
    p.push_back({x, 300 + amplitude * std::sin(x / 80.0) + jitter(random)});
  }
  return p;
}

TEST(PolylineSimplify, ShortLinesAreKept) {
  const Polyline two = {{0, 0}, {5, 5}};
  EXPECT_EQ(simplify_polyline(two), two);
  EXPECT_TRUE(simplify_polyline({}).empty());
}

TEST(PolylineSimplify, StraightRunCollapsesToItsEnds) {
  Polyline line;
  for (int i = 0; i <= 500; ++i) line.push_back({i * 2.0, 10 + i * 0.5});
  const Polyline out = simplify_polyline(line);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out.front(), line.front());
  EXPECT_EQ(out.back(), line.back());
}

TEST(PolylineSimplify, KeepsACornerExactly) {
  Polyline vee;
  for (int i = 0; i <= 100; ++i) vee.push_back({double(i), double(i < 50 ? i : 100 - i)});
  const Polyline out = simplify_polyline(vee);
  EXPECT_EQ(out.size(), 3u);
  EXPECT_LE(measured_deviation(vee, out), 0.3);
}

TEST(PolylineSimplify, EveryPointStaysWithinTheTolerance) {
  for (const double tolerance : {0.1, 0.3, 1.0, 4.0}) {
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const Polyline in = sine_curve(2000, 200.0, 0.5, seed);
      const Polyline out = simplify_polyline(in, tolerance);
      const double deviation = measured_deviation(in, out);
      EXPECT_LE(deviation, tolerance) << "tolerance " << tolerance << ", seed " << seed;
      EXPECT_LT(out.size(), in.size());
    }
  }
}

TEST(PolylineSimplify, SmoothCurveNeedsFewPoints) {
  const Polyline in = sine_curve(4000, 200.0, 0.0, 1);
  const Polyline out = simplify_polyline(in, 0.3);
  EXPECT_LE(measured_deviation(in, out), 0.3);
  EXPECT_LT(out.size(), in.size() / 10) << out.size() << " of " << in.size();
}

TEST(PolylineSimplify, ClosedLoopKeepsBothEnds) {
  Polyline circle;
  for (int i = 0; i <= 720; ++i) {
    const double a = 2 * std::numbers::pi * i / 720;
    circle.push_back({400 + 300 * std::cos(a), 400 + 300 * std::sin(a)});
  }
  const Polyline out = simplify_polyline(circle, 0.3);
  EXPECT_LE(measured_deviation(circle, out), 0.3);
  EXPECT_GT(out.size(), 20u);  // a 300 px circle needs ~ π / acos(1 - 0.3/300) ≈ 70 chords
}

TEST(PolylineSimplify, RepeatedPointsAreHandled) {
  const Polyline in = {{1, 1}, {1, 1}, {1, 1}, {4, 1}, {4, 1}, {4, 5}, {4, 5}};
  const Polyline out = simplify_polyline(in, 0.3);
  EXPECT_LE(measured_deviation(in, out), 0.3);
  EXPECT_EQ(out.size(), 3u);
}

}  // namespace
}  // namespace polarform::studio
