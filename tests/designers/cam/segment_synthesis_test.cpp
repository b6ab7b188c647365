// Constrained segments: the Hermite polynomial and the smoothest B-spline meet every prescribed
// endpoint value, reproduce the closed-form minimisers (the least-jerk curve under s, v, a end
// conditions is the 3-4-5 quintic; the least-bending one under s, v is the cubic Hermite), and
// their exact B-spline forms equal their evaluations.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "designers/cam/hermite_polynomial.h"
#include "designers/cam/motion_law.h"
#include "designers/cam/motion_segment.h"
#include "designers/cam/smoothest_bspline.h"
#include "src/error.h"

namespace polarform {
namespace {

// Endpoint values to 1e-10 relative to the size of that derivative over the segment (the
// rounding floor of evaluating a k-th derivative from control values).
void expect_endpoints(const std::function<void(double, int, double*)>& f, double u0, double u1,
                      const std::vector<double>& a, const std::vector<double>& b) {
  double d0[4], d1[4];
  const int k = static_cast<int>(a.size()) - 1;
  f(u0, k, d0);
  f(u1, k, d1);
  double scale[4] = {1, 1, 1, 1};
  for (int j = 0; j <= 200; ++j) {
    double d[4];
    f(u0 + (u1 - u0) * j / 200, k, d);
    for (int i = 0; i <= k; ++i) scale[i] = std::max(scale[i], std::abs(d[i]));
  }
  for (int i = 0; i <= k; ++i) {
    EXPECT_NEAR(d0[i], a[i], 1e-10 * scale[i]) << "start derivative " << i;
    EXPECT_NEAR(d1[i], b[i], 1e-10 * scale[i]) << "end derivative " << i;
  }
}

TEST(HermitePolynomial, MeetsArbitraryEndpointValues) {
  const std::vector<std::pair<std::vector<double>, std::vector<double>>> cases = {
      {{2.0}, {5.0}},
      {{1.0, -3.0}, {4.0, 2.5}},
      {{0.0, 1.5, -20.0}, {12.0, -2.0, 7.0}},
      {{3.0, 0.0, 0.0, 40.0}, {-1.0, -5.0, 30.0, -200.0}},
  };
  for (const auto& [a, b] : cases) {
    const Polynomial p = hermite_polynomial(0.7, 1.9, a, b);
    EXPECT_EQ(p.degree(), 2 * static_cast<int>(a.size()) - 1);
    expect_endpoints([&](double u, int d, double* o) { p.derivatives(u, d, o); }, 0.7, 1.9, a, b);
    const BSplineFunction bez = p.bezier(p.degree() + 2);  // elevated Bezier form is the same function
    for (double u = 0.7; u <= 1.9; u += 0.01) {
      double d[3];
      p.derivatives(u, 2, d);
      const Eigen::VectorXd e = bez.derivatives(u, 2);
      for (int k = 0; k <= 2; ++k) EXPECT_NEAR(e(k), d[k], 1e-10 * std::max(1.0, std::abs(d[k])));
    }
  }
}

// With zero end velocities and accelerations the Hermite quintic is the 3-4-5 law, and with zero
// jerks too the degree-7 polynomial is the 4-5-6-7 law.
TEST(HermitePolynomial, ReproducesThePolynomialLaws) {
  const double zero3[3] = {0, 0, 0}, one3[3] = {1, 0, 0}, zero4[4] = {0, 0, 0, 0}, one4[4] = {1, 0, 0, 0};
  const Polynomial quintic = hermite_polynomial(0.0, 1.0, zero3, one3);
  const Polynomial septic = hermite_polynomial(0.0, 1.0, zero4, one4);
  const Polynomial p345 = *standard_law_polynomial(MotionLaw::Polynomial345);
  const Polynomial p4567 = *standard_law_polynomial(MotionLaw::Polynomial4567);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(quintic.coefficients()[i], p345.coefficients()[i], 1e-12);
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(septic.coefficients()[i], p4567.coefficients()[i], 1e-11);
}

// Euler-Lagrange: the minimiser of ∫ f'''² with f, f', f'' fixed at both ends satisfies f^(6) = 0,
// so it is the quintic Hermite polynomial — which the B-spline space (degree 5) contains.
TEST(SmoothestBSpline, LeastJerkIsTheHermiteQuintic) {
  const std::vector<double> a = {1.0, 0.5, -2.0}, b = {11.0, 0.0, 3.0};
  const BSplineFunction f = smoothest_bspline(0.4, 1.6, a, b, {5, 14, 3});
  const Polynomial q = hermite_polynomial(0.4, 1.6, a, b);
  expect_endpoints([&](double u, int d, double* o) {
    const Eigen::VectorXd v = f.derivatives(u, d);
    for (int i = 0; i <= d; ++i) o[i] = v(i);
  }, 0.4, 1.6, a, b);
  for (double u = 0.4; u <= 1.6; u += 0.003) {
    double d[4];
    q.derivatives(u, 3, d);
    const Eigen::VectorXd v = f.derivatives(u, 3);
    EXPECT_NEAR(v(0), d[0], 1e-10);
    EXPECT_NEAR(v(3), d[3], 1e-7 * std::max(1.0, std::abs(d[3])));
  }
}

// ∫ f''² with f, f' fixed: f'''' = 0, the cubic Hermite polynomial (degree 4 B-spline, 9 values).
TEST(SmoothestBSpline, LeastBendingIsTheHermiteCubic) {
  const std::vector<double> a = {0.0, 2.0}, b = {5.0, -1.0};
  const BSplineFunction f = smoothest_bspline(0.0, 2.0, a, b, {4, 9, 2});
  const Polynomial q = hermite_polynomial(0.0, 2.0, a, b);
  for (double u = 0.0; u <= 2.0; u += 0.01) EXPECT_NEAR(f(u), q(u), 1e-11);
}

// A case without closed form: the constraints hold and the objective is below that of the
// Hermite quintic (which is feasible and in the spline space).
TEST(SmoothestBSpline, ConstraintsHoldAndObjectiveIsMinimal) {
  const std::vector<double> a = {0.0, 0.0, 0.0, 0.0}, b = {8.0, 0.0, 0.0, 0.0};
  const BSplineFunction f = smoothest_bspline(0.0, 1.5, a, b, {7, 16, 3});
  expect_endpoints([&](double u, int d, double* o) {
    const Eigen::VectorXd v = f.derivatives(u, d);
    for (int i = 0; i <= d; ++i) o[i] = v(i);
  }, 0.0, 1.5, a, b);
  const Polynomial q = hermite_polynomial(0.0, 1.5, a, b);
  double jf = 0, jq = 0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double u = 1.5 * (i + 0.5) / n;
    double d[4];
    q.derivatives(u, 3, d);
    jf += std::pow(f.derivatives(u, 3)(3), 2) * 1.5 / n;
    jq += d[3] * d[3] * 1.5 / n;
  }
  EXPECT_LT(jf, jq * (1 - 1e-3));
}

TEST(SmoothestBSpline, RejectsSettingsThatCannotDetermineIt) {
  const std::vector<double> a = {0.0, 0.0}, b = {1.0, 0.0};
  EXPECT_THROW(smoothest_bspline(0, 1, a, b, {5, 3, 3}), InputError);   // too few control values
  EXPECT_THROW(smoothest_bspline(0, 1, a, b, {5, 10, 6}), InputError);  // r above the degree
  EXPECT_THROW(smoothest_bspline(0, 1, a, b, {5, 10, 5}), InputError);  // r > 4 conditions
}

TEST(MotionSegment, PolynomialAndBSplineSegmentsMeetTheirConstraints) {
  SegmentSpec spec;
  spec.name = "rise";
  spec.kind = SegmentKind::Rise;
  spec.start = 0.5;
  spec.end = 2.0;
  spec.lift = 12.0;
  spec.constrained_order = 3;
  spec.at_start = {1.5, -3.0, 10.0};
  spec.at_end = {-0.5, 2.0, -4.0};
  for (MotionLaw law : {MotionLaw::Polynomial, MotionLaw::BSpline}) {
    spec.law = law;
    spec.bspline = {7, 12, 4};
    const MotionSegment seg(spec, 3.0);
    EXPECT_EQ(seg.end_level(), 15.0);
    expect_endpoints([&](double u, int d, double* o) { seg.derivatives(u, d, o); }, 0.5, 2.0,
                     {3.0, 1.5, -3.0, 10.0}, {15.0, -0.5, 2.0, -4.0});
    const BSplineFunction e = *seg.exact();
    for (double u = 0.5; u <= 2.0; u += 0.01) {
      double d[3];
      seg.derivatives(u, 2, d);
      const Eigen::VectorXd v = e.derivatives(u, 2);
      for (int k = 0; k <= 2; ++k) EXPECT_NEAR(v(k), d[k], 1e-9 * std::max(1.0, std::abs(d[k])));
    }
  }
}

}  // namespace
}  // namespace polarform
