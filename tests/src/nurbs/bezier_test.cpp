// Bezier decomposition (A5.6) and recomposition: every piece evaluated on its own by de Casteljau
// matches the B-spline (rational, clamped and unclamped), recomposition is exact, and malformed
// segments raise InputError.
#include "src/nurbs/bezier.h"

#include <gtest/gtest.h>

#include "src/error.h"
#include "src/nurbs/knot_removal.h"
#include "src/nurbs/periodic.h"
#include "tests/src/nurbs/kernel_test_support.h"

namespace polarform {
namespace {

using test::max_deviation;

// De Casteljau at local parameter s in [0, 1]: independent of the B-spline evaluation.
Eigen::VectorXd de_casteljau(Eigen::MatrixXd P, double s) {
  for (Eigen::Index r = 1; r < P.cols(); ++r)
    for (Eigen::Index i = 0; i < P.cols() - r; ++i)
      P.col(i) = (1 - s) * P.col(i) + s * P.col(i + 1);
  return P.col(0);
}

double piece_deviation(const BSpline& c, const BezierSegments& b, bool rational) {
  double worst = 0.0;
  for (std::size_t i = 0; i < b.segments.size(); ++i) {
    for (int k = 0; k <= 50; ++k) {
      const double s = k / 50.0, u = b.breaks[i] + s * (b.breaks[i + 1] - b.breaks[i]);
      Eigen::VectorXd x = de_casteljau(b.segments[i], s), y = c.point(u);
      if (rational) {
        const Eigen::Index d = x.size() - 1;
        x = (x.head(d) / x(d)).eval();
        y = (y.head(d) / y(d)).eval();
      }
      if (k == 50 && i + 1 < b.segments.size()) continue;  // u at the break is the next piece's
      worst = std::max(worst, (x - y).norm());
    }
  }
  return worst;
}

TEST(Bezier, PiecesMatchTheSplineAndRecomposeExactly) {
  std::mt19937 rng(31);
  double worst = 0.0;
  for (int p = 1; p <= 8; ++p) {
    const BSpline c = test::random_rational(rng, p, test::random_knots(rng, p, -1.0, 2.0, 7, p), 3);
    const BezierSegments b = decompose_bezier(c);
    ASSERT_EQ(b.degree, p);
    ASSERT_EQ(b.segments.size() + 1, b.breaks.size());
    EXPECT_EQ(b.breaks.size(), breakpoints(c.knots()).size());
    worst = std::max(worst, piece_deviation(c, b, true));
    const BSpline back = compose_bezier(b);
    worst = std::max(worst, max_deviation(c, back, 800, true));
    // Interior breaks of multiplicity p (the pieces share end points); removal recovers c's knots.
    for (std::size_t i = 1; i + 1 < b.breaks.size(); ++i)
      EXPECT_EQ(multiplicity(back.knots(), b.breaks[i]), p);
    EXPECT_EQ(remove_removable_knots(back, 1e-10).knots(), c.knots());
  }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_deviation", test::sci(worst));
}

TEST(Bezier, UnclampedPeriodicSpline) {
  std::mt19937 rng(32);
  const BSpline c =
      periodic_bspline(4, {0.0, 0.5, 1.25, 2.0, 3.0, 3.5}, test::random_coefs(rng, 2, 5));
  const BezierSegments b = decompose_bezier(c);
  EXPECT_EQ(b.breaks, (std::vector<double>{0.0, 0.5, 1.25, 2.0, 3.0, 3.5}));
  EXPECT_LT(piece_deviation(c, b, false), 1e-12);
  EXPECT_LT(max_deviation(c, compose_bezier(b), 800, false), 1e-12);
}

TEST(Bezier, StackOnFinerBreaks) {
  std::mt19937 rng(33);
  const BSpline c = test::random_bspline(rng, 3, {0, 0, 0, 0, 1, 2, 2, 2, 2}, 2);
  const Eigen::MatrixXd S = bezier_stack(c, {0.0, 0.5, 1.0, 1.75, 2.0});
  ASSERT_EQ(S.cols(), 16);
  const std::vector<double> breaks{0.0, 0.5, 1.0, 1.75, 2.0};
  for (int i = 0; i < 4; ++i)
    for (double s : {0.0, 0.3, 0.9}) {
      const double u = breaks[i] + s * (breaks[i + 1] - breaks[i]);
      EXPECT_LT((de_casteljau(S.middleCols(4 * i, 4), s) - c.point(u)).norm(), 1e-14);
    }
  EXPECT_THROW(bezier_stack(c, {0.0, 0.5, 2.0}), InputError);  // misses the knot 1
  EXPECT_THROW(bezier_stack(c, {0.0, 1.0, 1.5}), InputError);  // stops short of the end
}

TEST(Bezier, DiscontinuousPiecesKeepBothEnds) {
  BezierSegments b{2, {0.0, 1.0, 3.0}, {}};
  b.segments.push_back((Eigen::MatrixXd(1, 3) << 0, 1, 2).finished());
  b.segments.push_back((Eigen::MatrixXd(1, 3) << 5, 4, 3).finished());
  const BSpline c = compose_bezier(b);
  EXPECT_EQ(c.knots(), (Knots{0, 0, 0, 1, 1, 1, 3, 3, 3}));
  EXPECT_DOUBLE_EQ(c.point(1.0)(0), 5.0);            // right piece at the break
  EXPECT_NEAR(c.point(1.0 - 1e-12)(0), 2.0, 1e-11);  // the left piece just before it
  b.segments[1].resize(1, 2);
  EXPECT_THROW(compose_bezier(b), InputError);
  b.segments[1] = (Eigen::MatrixXd(1, 3) << 2, 4, 3).finished();
  b.breaks[1] = 3.0;
  EXPECT_THROW(compose_bezier(b), InputError);
}

}  // namespace
}  // namespace polarform
