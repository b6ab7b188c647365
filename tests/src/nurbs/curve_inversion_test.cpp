// Closest point on a curve: against dense brute-force sampling on random rational curves, the
// orthogonality of the residual at interior solutions, points on the curve, end minima, and closed
// base circles (closed form: the radial projection).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "src/base/base_circle.h"
#include "src/error.h"
#include "src/nurbs/knots.h"
#include "src/nurbs/point_inversion.h"

namespace polarform {
namespace {

template <int D>
NurbsCurve<D> random_curve(std::mt19937& rng, int degree, int n) {
  std::uniform_real_distribution<double> coord(-1.0, 1.0), weight(0.3, 3.0), unit(0.0, 1.0);
  typename NurbsCurve<D>::Points points(n);
  std::vector<double> weights(n);
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < D; ++k) points[i][k] = coord(rng);
    weights[i] = weight(rng);
  }
  // Interior knots with multiplicity up to degree − 1 (C1 or smoother), on [−0.5, 2], at least
  // 0.05 apart (nearly coincident knots make |C'| huge and orthogonality unmeasurable at 1e-9).
  std::vector<double> interior;
  const int count = n - degree - 1;
  while (static_cast<int>(interior.size()) < count) {
    const double k = -0.5 + 2.5 * unit(rng);
    if (k < -0.45 || k > 1.95) continue;
    if (std::any_of(interior.begin(), interior.end(), [&](double x) { return std::abs(x - k) < 0.05; }))
      continue;
    const int left = count - static_cast<int>(interior.size());
    interior.insert(interior.end(), std::min(left, 1 + static_cast<int>(unit(rng) * (degree - 1))), k);
  }
  std::sort(interior.begin(), interior.end());
  return NurbsCurve<D>(degree, clamped_knots(degree, -0.5, 2.0, interior), points, weights);
}

// Minimum distance over a dense sample of the curve (samples precomputed as matrix columns).
template <int D>
Eigen::Matrix<double, D, Eigen::Dynamic> dense_samples(const NurbsCurve<D>& c, int n) {
  Eigen::Matrix<double, D, Eigen::Dynamic> out(D, n + 1);
  for (int i = 0; i <= n; ++i) out.col(i) = c(c.front() + (c.back() - c.front()) * i / n);
  return out;
}

template <int D>
void check_against_brute_force(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-1.5, 1.5);
  int interior = 0, ends = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const int degree = 2 + trial % 4;
    const NurbsCurve<D> c = random_curve<D>(rng, degree, degree + 2 + trial % 5);
    const auto dense = dense_samples(c, 40000);
    for (int k = 0; k < 150; ++k) {
      Eigen::Matrix<double, D, 1> p;
      for (int i = 0; i < D; ++i) p[i] = coord(rng);
      const CurveProjection r = closest_point(c, p);
      const double brute = std::sqrt((dense.colwise() - p).colwise().squaredNorm().minCoeff());
      ASSERT_LE(r.distance, brute + 1e-12) << "trial " << trial << " point " << k;
      EXPECT_NEAR((c(r.u) - r.point).norm(), 0.0, 1e-15);
      EXPECT_NEAR((r.point - p).norm(), r.distance, 1e-15);
      if (r.u > c.front() && r.u < c.back()) {
        const auto d = c.derivatives(r.u, 1);
        const Eigen::Matrix<double, D, 1> res = d[0] - p;
        EXPECT_LT(std::abs(d[1].dot(res)) / (d[1].norm() * res.norm()), 1e-9);
        ++interior;
      } else {
        ++ends;
      }
    }
  }
  // Both kinds of solution were exercised.
  EXPECT_GT(interior, 500);
  EXPECT_GT(ends, 20);
}

TEST(CurveInversion, RandomPlanarCurvesAgainstBruteForce) { check_against_brute_force<2>(1); }
TEST(CurveInversion, RandomSpaceCurvesAgainstBruteForce) { check_against_brute_force<3>(2); }

TEST(CurveInversion, PointsOnTheCurve) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 10; ++trial) {
    const NurbsCurve3d c = random_curve<3>(rng, 2 + trial % 4, 8);
    for (int k = 0; k < 200; ++k) {
      const double u = c.front() + (c.back() - c.front()) * unit(rng);
      EXPECT_LT(closest_point(c, Eigen::Vector3d(c(u))).distance, 1e-12);
    }
  }
}

// A straight cubic from (0,0) to (3,0) (uniform speed is not needed): points beyond the ends
// project onto the ends, points beside it onto their foot.
TEST(CurveInversion, EndMinimaAndFeet) {
  const NurbsCurve2d c(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {0.5, 0}, {2.8, 0}, {3, 0}}, {1, 2, 0.5, 1});
  const CurveProjection before = closest_point(c, Eigen::Vector2d(-1, 0.5));
  EXPECT_EQ(before.u, 0.0);
  EXPECT_NEAR(before.distance, std::hypot(1.0, 0.5), 1e-15);
  const CurveProjection after = closest_point(c, Eigen::Vector2d(4, -2));
  EXPECT_EQ(after.u, 1.0);
  EXPECT_NEAR(after.distance, std::hypot(1.0, 2.0), 1e-15);
  for (double x = 0.05; x < 3; x += 0.1) {
    const CurveProjection r = closest_point(c, Eigen::Vector2d(x, 0.7));
    EXPECT_NEAR(r.point.x(), x, 1e-14);
    EXPECT_NEAR(r.distance, 0.7, 1e-14);
  }
}

// Closed base circles: the closest point is the radial projection, also at and around the seam.
TEST(CurveInversion, ClosedCircles) {
  constexpr double kPi = std::numbers::pi;
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> angle(-kPi, kPi), radius(0.05, 3.0), tiny(-1e-9, 1e-9);
  for (ArcKind kind : {ArcKind::rqb, ArcKind::quartic})
    for (int arcs : {3, 4, 6}) {
      const double start = -1.0;
      const BaseCircle b = BaseCircle::equal_arcs(kind, start, start + 2 * kPi, arcs);
      for (int k = 0; k < 400; ++k) {
        const double t = k % 4 == 0 ? start + tiny(rng) : angle(rng), r = radius(rng);
        const Eigen::Vector2d p(r * std::cos(t), r * std::sin(t));
        const CurveProjection proj = closest_point(b.curve(), p);
        EXPECT_NEAR(proj.distance, std::abs(r - 1.0), 1e-14);
        EXPECT_NEAR(std::remainder(std::atan2(proj.point.y(), proj.point.x()) - t, 2 * kPi), 0.0,
                    1e-13);
      }
    }
}

TEST(CurveInversion, BadInputThrows) {
  const NurbsCurve2d c(1, {0, 0, 1, 1}, {{0, 0}, {1, 0}});
  EXPECT_THROW(closest_point(c, Eigen::Vector2d(NAN, 0)), InputError);
}

// Regression: a foot whose root of C'·(C − P) falls on a Bernstein subdivision point does not
// bracket in floating point; it was missed (C(0.3) of this spine came back 0.0318 away).
TEST(CurveInversion, ARootOnASubdivisionPointIsFound) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  NurbsCurve3d::Points points(8);
  for (auto& p : points) p = {coord(rng), coord(rng), coord(rng)};
  const NurbsCurve3d c(3, uniform_clamped_knots(3, 5, 0.0, 1.0), points);
  for (int k = 1; k < 100; ++k) {
    const double t = k / 100.0;
    const CurveProjection f = closest_point(c, Eigen::Vector3d(c.point(t)));
    EXPECT_LT(f.distance, 1e-14) << t;
  }
}

}  // namespace
}  // namespace polarform
