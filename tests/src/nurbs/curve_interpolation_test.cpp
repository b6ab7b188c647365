// Cubic interpolation with knots at the data parameters: through every point, natural ends
// (C″ = 0), and exact on a cubic polynomial when its end tangents are given; Bessel ends are
// exact on a parabola, so the interpolant with them reproduces it.
#include "src/nurbs/curve_interpolation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "src/error.h"

namespace polarform {
namespace {

TEST(CubicInterpolation, PassesThroughThePointsWithNaturalEnds) {
  Eigen::MatrixXd p(2, 12);
  Eigen::VectorXd t(12);
  for (int k = 0; k < 12; ++k) {
    t[k] = k + 0.3 * std::sin(k);
    p.col(k) = Eigen::Vector2d(std::cos(0.4 * t[k]), std::exp(0.1 * t[k]));
  }
  const BSpline c = interpolate_cubic(p, t);
  for (int k = 0; k < 12; ++k) EXPECT_LT((c.point(t[k]) - p.col(k)).norm(), 1e-13);
  EXPECT_LT(c.derivatives(t[0], 2).col(2).norm(), 1e-12);
  EXPECT_LT(c.derivatives(t[11], 2).col(2).norm(), 1e-12);
}

TEST(CubicInterpolation, ReproducesACubicGivenItsEndTangents) {
  const auto f = [](double x) { return 2 - x + 0.5 * x * x - 0.1 * x * x * x; };
  const auto df = [](double x) { return -1 + x - 0.3 * x * x; };
  Eigen::MatrixXd v(1, 7);
  Eigen::VectorXd t(7);
  for (int k = 0; k < 7; ++k) t[k] = k * k * 0.2, v(0, k) = f(t[k]);
  CubicEnds ends;
  ends.start_tangent = Eigen::VectorXd::Constant(1, df(t[0]));
  ends.end_tangent = Eigen::VectorXd::Constant(1, df(t[6]));
  const BSpline c = interpolate_cubic(v, t, ends);
  for (int k = 0; k <= 100; ++k) {
    const double x = t[6] * k / 100;
    EXPECT_NEAR(c.point(x)(0), f(x), 1e-12);
  }
}

TEST(CubicInterpolation, BesselEndsReproduceAParabola) {
  Eigen::MatrixXd p(1, 7);
  Eigen::VectorXd t(7);
  const auto f = [](double x) { return 2.0 - 0.7 * x + 0.3 * x * x; };
  for (int k = 0; k < 7; ++k) {
    t[k] = k + 0.4 * std::cos(k);
    p(0, k) = f(t[k]);
  }
  const CubicEnds ends = bessel_ends(p, t);
  EXPECT_NEAR((*ends.start_tangent)[0], -0.7 + 0.6 * t[0], 1e-12);
  EXPECT_NEAR((*ends.end_tangent)[0], -0.7 + 0.6 * t[6], 1e-12);
  const BSpline c = interpolate_cubic(p, t, ends);
  for (int k = 0; k <= 200; ++k) {
    const double x = t[0] + (t[6] - t[0]) * k / 200.0;
    EXPECT_NEAR(c.point(x)[0], f(x), 1e-12) << x;
  }
  EXPECT_THROW(bessel_ends(p.leftCols(2), t.head(2)), InputError);
}

TEST(CubicInterpolation, RefusesParametersThatDoNotIncrease) {
  Eigen::MatrixXd v = Eigen::MatrixXd::Zero(1, 3);
  EXPECT_THROW(interpolate_cubic(v, Eigen::Vector3d(0, 1, 1)), InputError);
  EXPECT_THROW(interpolate_cubic(v, Eigen::Vector2d(0, 1)), InputError);
}

}  // namespace
}  // namespace polarform
