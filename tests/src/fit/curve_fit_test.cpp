// Parametric least-squares curve fit (spec B1 acceptance): a segment reproduced at degrees 1 and
// 3, a cubic Bézier with fixed ends recovered (and agreeing with a QR solve), an L-shaped polyline
// exact with a corner knot and ≥ 10× worse without, a periodic ellipse closed to C^{p−1}, and the
// tolerance loop meeting its tolerance on a smooth curve.
#include "src/fit/curve_fit.h"

#include <gtest/gtest.h>

#include <Eigen/QR>
#include <cmath>
#include <numbers>

#include "src/fit/corner_detection.h"
#include "src/nurbs/knots.h"

namespace polarform {
namespace {

TEST(CurveFit, SegmentIsReproducedAtDegreesOneAndThree) {
  Eigen::Matrix2Xd P(2, 200);
  for (int i = 0; i < 200; ++i) {
    const double t = std::pow(i / 199.0, 1.3);  // uneven spacing
    P.col(i) = Eigen::Vector2d(1, 2) + t * Eigen::Vector2d(3, -7);
  }
  for (int p : {1, 3}) {
    CurveFitOptions<2> o;
    o.degree = p;
    o.control_points = p + 3;
    const CurveFit<2> f = fit_curve<2>(P, o);
    EXPECT_LE(f.max_distance, 1e-12) << "degree " << p;
    const Eigen::Vector2d n(7, 3);
    for (const auto& c : f.curve.control_points())
      EXPECT_NEAR((c - Eigen::Vector2d(1, 2)).dot(n.normalized()), 0.0, 1e-12);
  }
}

TEST(CurveFit, CubicBezierWithFixedEndsComesBackExactly) {
  std::vector<Eigen::Vector2d> B{{0, 0}, {1, 3}, {4, 3.5}, {6, -1}};
  const NurbsCurve2d truth(3, clamped_knots(3, 0, 1), B);
  Eigen::Matrix2Xd P(2, 50);
  Eigen::VectorXd u(50);
  for (int i = 0; i < 50; ++i) {
    u[i] = std::pow(i / 49.0, 0.8);
    P.col(i) = truth.point(u[i]);
  }
  CurveFitOptions<2> o;
  o.control_points = 4;
  o.fix_ends = true;
  o.parameters = u;
  o.correction_rounds = 0;
  const CurveFit<2> f = fit_curve<2>(P, o);
  for (int j = 0; j < 4; ++j) EXPECT_LE((f.curve.control_point(j) - B[j]).norm(), 1e-12);
  EXPECT_EQ(f.curve.control_point(0), P.col(0));
  EXPECT_EQ(f.curve.control_point(3), P.col(49));
  // MIT (8.5)–(8.10) by Householder QR of the 48 x 2 interior system.
  Eigen::MatrixXd A(48, 2), rhs(48, 2);
  for (int i = 1; i < 49; ++i) {
    const double t = u[i], s = 1 - t;
    A.row(i - 1) << 3 * t * s * s, 3 * t * t * s;
    rhs.row(i - 1) = (P.col(i) - s * s * s * P.col(0) - t * t * t * P.col(49)).transpose();
  }
  const Eigen::MatrixXd X = A.householderQr().solve(rhs);
  for (int j = 1; j <= 2; ++j)
    EXPECT_LE((f.curve.control_point(j) - X.row(j - 1).transpose()).norm(), 1e-12);
}

Eigen::Matrix2Xd l_shape() {
  Eigen::Matrix2Xd P(2, 400);
  for (int i = 0; i < 400; ++i) {
    const double s = 20.0 * i / 399.0;
    P.col(i) = s <= 10 ? Eigen::Vector2d(s, 0) : Eigen::Vector2d(10, s - 10);
  }
  return P;
}

TEST(CurveFit, CornerKnotMakesAnLShapeExact) {
  const Eigen::Matrix2Xd P = l_shape();
  const std::vector<int> corners = detect_corners<2>(P, false, 30 * std::numbers::pi / 180, 5);
  ASSERT_EQ(corners.size(), 1u);
  EXPECT_NEAR(P(0, corners[0]), 10.0, 0.03);
  CurveFitOptions<2> o;
  o.control_points = 7;
  o.corners = corners;
  const CurveFit<2> with = fit_curve<2>(P, o);
  EXPECT_LE(with.max_distance, 1e-9);
  ASSERT_EQ(with.corner_parameters.size(), 1u);
  EXPECT_EQ(multiplicity(with.curve.knots(), with.corner_parameters[0]), 3);
  o.corners.clear();
  const CurveFit<2> without = fit_curve<2>(P, o);
  EXPECT_GE(without.max_distance, 10 * std::max(with.max_distance, 1e-9));
}

TEST(CurveFit, PeriodicEllipseClosesWithContinuousDerivatives) {
  Eigen::Matrix2Xd P(2, 360);
  for (int i = 0; i < 360; ++i) {
    const double t = 2 * std::numbers::pi * i / 360;
    P.col(i) << 10 * std::cos(t), 5 * std::sin(t);
  }
  CurveFitOptions<2> o;
  o.closed = true;
  o.tolerance = 1e-4;
  const CurveFit<2> f = fit_curve<2>(P, o);
  EXPECT_TRUE(f.tolerance_met);
  EXPECT_LE(f.max_distance, 1e-4);
  const auto a = f.curve.derivatives(0.0, 2), b = f.curve.derivatives(1.0, 2);
  EXPECT_LE((a[0] - b[0]).norm(), 1e-12);
  EXPECT_LE((a[1] - b[1]).norm(), 1e-9 * a[1].norm());
  EXPECT_LE((a[2] - b[2]).norm(), 1e-9 * a[2].norm());
}

TEST(CurveFit, ClosedRectangleWithCornersIsExact) {
  Eigen::Matrix2Xd P(2, 120);
  for (int i = 0; i < 120; ++i) {
    const double s = 60.0 * i / 120;  // perimeter 60 of a 20 x 10 rectangle
    P.col(i) = s < 20   ? Eigen::Vector2d(s, 0)
               : s < 30 ? Eigen::Vector2d(20, s - 20)
               : s < 50 ? Eigen::Vector2d(50 - s, 10)
                        : Eigen::Vector2d(0, 60 - s);
  }
  const std::vector<int> corners = detect_corners<2>(P, true, 30 * std::numbers::pi / 180, 3);
  EXPECT_EQ(corners, (std::vector<int>{0, 40, 60, 100}));
  CurveFitOptions<2> o;
  o.closed = true;
  o.corners = corners;
  o.tolerance = 1e-9;
  const CurveFit<2> f = fit_curve<2>(P, o);
  EXPECT_LE(f.max_distance, 1e-9);
  EXPECT_LE((f.curve.point(0) - f.curve.point(1)).norm(), 1e-12);
}

TEST(CurveFit, ToleranceLoopMeetsTheToleranceIn3d) {
  Eigen::Matrix3Xd P(3, 2000);
  for (int i = 0; i < 2000; ++i) {
    const double t = 6 * std::numbers::pi * i / 1999;
    P.col(i) << 5 * std::cos(t), 5 * std::sin(t), 0.8 * t;
  }
  CurveFitOptions<3> o;
  o.tolerance = 1e-5;
  const CurveFit<3> f = fit_curve<3>(P, o);
  EXPECT_TRUE(f.tolerance_met);
  EXPECT_LE(f.max_distance, 1e-5);
  EXPECT_LE(f.curve.size(), 200);
}

}  // namespace
}  // namespace polarform
