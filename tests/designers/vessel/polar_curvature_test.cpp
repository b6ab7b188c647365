// Polar curvature (DESIGN §4.4) against closed forms, its gradient against finite differences, and
// the exact polar forms of circles and ellipses against their implicit equations and differences.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/vessel/meridian_arcs.h"
#include "designers/vessel/polar_curvature.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(PolarCurvature, CircleAboutTheOrigin) {
  EXPECT_DOUBLE_EQ(polar_curvature(250.0, 0.0, 0.0), 1.0 / 250.0);
  const PolarCurvature g = polar_curvature_with_gradient(250.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(g.kappa, 1.0 / 250.0);
  EXPECT_DOUBLE_EQ(g.d_r, -1.0 / (250.0 * 250.0));  // κ = 1/R
  EXPECT_DOUBLE_EQ(g.d_ddr, -1.0 / (250.0 * 250.0));
  EXPECT_EQ(g.d_dr, 0.0);
}

// Ellipse (a cos t, b sin t): κ = ab / (a² sin²t + b² cos²t)^{3/2}.
TEST(PolarCurvature, EllipseMatchesParametricCurvature) {
  const double a = 500, b = 250;
  for (int i = 0; i <= 36; ++i) {
    const double t = kPi * i / 36, theta = std::atan2(b * std::sin(t), a * std::cos(t));
    double d[4];
    ellipse_polar(a, b, theta, 3, d);
    const double q = a * a * std::sin(t) * std::sin(t) + b * b * std::cos(t) * std::cos(t);
    EXPECT_NEAR(d[0], std::hypot(a * std::cos(t), b * std::sin(t)), 1e-12 * a);
    EXPECT_NEAR(polar_curvature(d[0], d[1], d[2]), a * b / std::pow(q, 1.5), 1e-12 / b) << t;
  }
}

TEST(PolarCurvature, GradientMatchesCentralDifferences) {
  const double x[3] = {480.0, -35.0, 1200.0};
  const PolarCurvature g = polar_curvature_with_gradient(x[0], x[1], x[2]);
  const double analytic[3] = {g.d_r, g.d_dr, g.d_ddr};
  for (int k = 0; k < 3; ++k) {
    double plus[3] = {x[0], x[1], x[2]}, minus[3] = {x[0], x[1], x[2]};
    const double h = 1e-4 * std::max(1.0, std::abs(x[k]));
    plus[k] += h;
    minus[k] -= h;
    const double fd = (polar_curvature(plus[0], plus[1], plus[2]) -
                       polar_curvature(minus[0], minus[1], minus[2])) / (2 * h);
    EXPECT_NEAR(analytic[k], fd, 1e-6 * std::abs(analytic[k])) << k;
  }
  EXPECT_DOUBLE_EQ(g.kappa, polar_curvature(x[0], x[1], x[2]));
}

// R^(k+1) against the central difference of R^(k), for k = 0, 1, 2, relative to max(1, |R^(k+1)|).
template <class F>
void expect_consistent_derivatives(F&& f, double theta) {
  const double h = 1e-5;
  double d[4], p[4], m[4];
  f(theta, 3, d);
  f(theta + h, 3, p);
  f(theta - h, 3, m);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(d[k + 1], (p[k] - m[k]) / (2 * h), 1e-6 * std::max(1.0, std::abs(d[k + 1])))
        << "order " << k + 1 << " at " << theta;
}

TEST(MeridianArcs, CirclePolarFormLiesOnTheCircle) {
  // Origin outside the circle (a knuckle); the rays from it touch the circle at about −10.4° and
  // +5.2°, so the far intersection is checked well inside, on [−8°, +3.5°].
  const double cx = 440, cz = -20, r = 60;
  for (int i = 0; i <= 20; ++i) {
    const double theta = (-8 + 11.5 * i / 20) * kPi / 180;
    double d[4];
    circle_polar(cx, cz, r, theta, 3, d);
    const double x = d[0] * std::cos(theta), z = d[0] * std::sin(theta);
    EXPECT_NEAR(std::hypot(x - cx, z - cz), r, 1e-11 * r);
    EXPECT_GT(d[0], std::hypot(cx, cz));  // the far intersection
    EXPECT_NEAR(polar_curvature(d[0], d[1], d[2]), 1 / r, 1e-10 / r);
    expect_consistent_derivatives([&](double t, int k, double* o) { circle_polar(cx, cz, r, t, k, o); },
                                  theta);
  }
  double d[4];
  circle_polar(0.0, -300.0, 1000.0, kPi / 2, 3, d);  // origin inside: the crown
  EXPECT_NEAR(d[0], 700.0, 1e-12 * 700);
  EXPECT_NEAR(d[1], 0.0, 1e-12);
}

TEST(MeridianArcs, EllipseDerivativesAreConsistent) {
  for (int i = 0; i <= 12; ++i)
    expect_consistent_derivatives([](double t, int k, double* o) { ellipse_polar(500, 250, t, k, o); },
                                  kPi * i / 12);
}

}  // namespace
}  // namespace polarform
