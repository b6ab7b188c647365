// Joining clamped curves (curve_join.h): the joined curve passes through every piece's points at
// the same parameters, has the pieces' control points less one per joint (after raising to the
// highest degree), a knot of multiplicity p at each joint, and bad pieces raise InputError.
#include "src/nurbs/curve_join.h"

#include <gtest/gtest.h>

#include "src/error.h"

namespace polarform {
namespace {

NurbsCurve2d polynomial_piece(int p, double a, double b, const Eigen::Vector2d& start,
                              const Eigen::Vector2d& end, double bulge) {
  NurbsCurve2d::Points points;
  for (int i = 0; i <= p + 1; ++i) {
    const double s = static_cast<double>(i) / (p + 1);
    points.push_back((1 - s) * start + s * end +
                     Eigen::Vector2d(0.0, bulge * s * (1 - s) * (i % 2 ? 1 : -1)));
  }
  return NurbsCurve2d(p, clamped_knots(p, a, b, {0.5 * (a + b)}), points);
}

TEST(CurveJoin, JoinedCurveIsEveryPieceAtItsParameters) {
  const Eigen::Vector2d A(0, 0), B(3, 1), C(5, -2);
  const NurbsCurve2d first = polynomial_piece(3, 0.0, 1.0, A, B, 0.7);
  const NurbsCurve2d second = polynomial_piece(5, 1.0, 2.5, B, C, -0.4);
  const NurbsCurve2d joined = join_curves({first, second});
  EXPECT_EQ(joined.degree(), 5);
  // The cubic raised to degree 5 (each of its 2 spans gains 2 control points), the joint once.
  EXPECT_EQ(joined.size(), (first.size() + 2 * 2) + second.size() - 1);
  EXPECT_EQ(multiplicity(joined.knots(), 1.0), 5);
  EXPECT_EQ(joined.front(), 0.0);
  EXPECT_EQ(joined.back(), 2.5);
  double worst = 0.0;
  for (int k = 0; k <= 200; ++k) {
    const double u = 2.5 * k / 200;
    const Eigen::Vector2d expected = u <= 1.0 ? first(u) : second(u);
    worst = std::max(worst, (joined(u) - expected).norm());
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(CurveJoin, GapsAndMisfitsAreErrors) {
  const NurbsCurve2d first = polynomial_piece(3, 0.0, 1.0, {0, 0}, {1, 1}, 0.2);
  EXPECT_THROW(join_curves({}), InputError);
  EXPECT_THROW(join_curves({first, polynomial_piece(3, 1.1, 2.0, {1, 1}, {2, 0}, 0.2)}),
               InputError);
  EXPECT_THROW(join_curves({first, polynomial_piece(3, 1.0, 2.0, {1, 1.1}, {2, 0}, 0.2)}),
               InputError);
}

}  // namespace
}  // namespace polarform
