// Basis functions, B-spline/NURBS curve and surface evaluation against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "src/error.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/bspline.h"
#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {
namespace {

TEST(Basis, PartitionOfUnityAndDerivativeSum) {
  const Knots U = {0, 0, 0, 0, 0.5, 1.25, 1.25, 2, 3, 3, 3, 3};
  const int p = 3, n = static_cast<int>(U.size()) - p - 1;
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> t(0.0, 3.0);
  for (int k = 0; k < 1000; ++k) {
    const double u = t(rng);
    const int span = find_span(p, U, n, u);
    ASSERT_LE(U[span], u);
    ASSERT_LT(u, U[span + 1] + (span == n - 1 ? 1e-300 : 0.0));
    const Eigen::MatrixXd D = ders_basis_funs(span, u, p, 3, U);
    EXPECT_NEAR(D.row(0).sum(), 1.0, 1e-15);
    for (int d = 1; d <= 3; ++d) EXPECT_NEAR(D.row(d).sum(), 0.0, 1e-12);
    double N[kMaxDegree + 1];
    basis_funs(span, u, p, U, N);
    for (int j = 0; j <= p; ++j) EXPECT_DOUBLE_EQ(N[j], D(0, j));
  }
}

// The batch on one span agrees with A2.2 at each parameter, on every span of a knot vector with
// a double knot, for degrees 1..10.
TEST(Basis, OnSpanAgreesWithOneParameterAtATime) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> fraction(0.0, 1.0);
  for (int p = 1; p <= 10; ++p) {
    Knots U(static_cast<std::size_t>(p + 1), 0.0);
    for (double b : {0.3, 0.7, 0.7, 1.6, 2.0}) U.push_back(b);
    U.insert(U.end(), static_cast<std::size_t>(p + 1), 3.0);
    const int n = static_cast<int>(U.size()) - p - 1;
    for (int span = p; span < n; ++span) {
      if (!(U[span + 1] > U[span])) continue;
      double u[7], N[7 * (kMaxDegree + 1)];
      for (double& v : u) v = U[span] + (U[span + 1] - U[span]) * fraction(rng);
      basis_funs_on_span(span, u, 7, p, U, N);
      for (int i = 0; i < 7; ++i) {
        double one[kMaxDegree + 1], sum = 0.0;
        basis_funs(span, u[i], p, U, one);
        for (int j = 0; j <= p; ++j) {
          EXPECT_NEAR(N[i * (p + 1) + j], one[j], 2e-15) << "p " << p << " span " << span;
          sum += N[i * (p + 1) + j];
        }
        EXPECT_NEAR(sum, 1.0, 2e-15);  // p + 1 rounded terms
      }
    }
  }
}

TEST(Basis, SpanAtDomainEnds) {
  const Knots U = {0, 0, 0, 1, 2, 2, 2};
  EXPECT_EQ(find_span(2, U, 4, 0.0), 2);
  EXPECT_EQ(find_span(2, U, 4, 1.0), 3);
  EXPECT_EQ(find_span(2, U, 4, 2.0), 3);
  EXPECT_EQ(find_span(2, U, 4, 5.0), 3);
}

// A cubic Bezier function reproduces its Bernstein polynomial and derivatives exactly.
TEST(BSplineFunction, BezierClosedForm) {
  const BSplineFunction f(3, {0, 0, 0, 0, 1, 1, 1, 1}, Eigen::Vector4d(1, -2, 4, 3));
  for (double u = 0; u <= 1.0; u += 0.125) {
    const double s = 1 - u;
    const double value = s * s * s + 3 * s * s * u * -2 + 3 * s * u * u * 4 + u * u * u * 3;
    const double d1 = 3 * (s * s * (-3) + 2 * s * u * 6 + u * u * (-1));
    const Eigen::VectorXd d = f.derivatives(u, 4);
    EXPECT_NEAR(f(u), value, 1e-15);
    EXPECT_NEAR(d(0), value, 1e-15);
    EXPECT_NEAR(d(1), d1, 1e-13);
    EXPECT_EQ(d(4), 0.0);
    EXPECT_NEAR(f.derivative()(u), d1, 1e-13);
  }
}

// The quarter circle as a rational quadratic Bezier: every point on the unit circle, and the
// derivatives match the closed form of the rational parametrisation.
TEST(NurbsCurve, QuarterCircleExact) {
  const double w = std::sqrt(0.5);
  const NurbsCurve2d c(2, {0, 0, 0, 1, 1, 1}, {{1, 0}, {1, 1}, {0, 1}}, {1, w, 1});
  EXPECT_TRUE(c.is_rational());
  for (int k = 0; k <= 100; ++k) {
    const double u = k / 100.0;
    EXPECT_NEAR(c(u).norm(), 1.0, 1e-15);
    const auto d = c.derivatives(u, 2);
    EXPECT_NEAR(d[0].dot(d[1]), 0.0, 1e-14);  // tangent of a circle is orthogonal to the radius
    // Curvature of the unit circle: |x'y'' - y'x''| / |C'|^3 = 1.
    const double cross = d[1].x() * d[2].y() - d[1].y() * d[2].x();
    EXPECT_NEAR(cross / std::pow(d[1].norm(), 3), 1.0, 1e-13);
  }
}

TEST(NurbsSurface, CylinderPatchExact) {
  const double w = std::sqrt(0.5);
  NurbsSurface::Points pts;
  std::vector<double> wts;
  for (double z : {0.0, 2.0})
    for (auto [x, y, wi] : {std::tuple{1.0, 0.0, 1.0}, {1.0, 1.0, w}, {0.0, 1.0, 1.0}}) {
      pts.emplace_back(x, y, z);
      wts.push_back(wi);
    }
  const NurbsSurface s(1, 2, {0, 0, 1, 1}, {0, 0, 0, 1, 1, 1}, pts, wts);
  for (double u = 0; u <= 1; u += 0.1)
    for (double v = 0; v <= 1; v += 0.1) {
      const auto p = s(u, v);
      EXPECT_NEAR(std::hypot(p.x(), p.y()), 1.0, 1e-15);
      EXPECT_NEAR(p.z(), 2 * u, 1e-15);
      const auto d = s.derivatives(u, v, 2);
      EXPECT_NEAR((d[1 * 3 + 0] - Eigen::Vector3d(0, 0, 2)).norm(), 0.0, 1e-14);  // S_u
      EXPECT_NEAR(d[0 * 3 + 1].dot(Eigen::Vector3d(p.x(), p.y(), 0)), 0.0, 1e-14);  // S_v ⟂ radius
      EXPECT_NEAR(d[2 * 3 + 0].norm(), 0.0, 1e-13);                                 // S_uu
      EXPECT_NEAR(s.normal(u, v).dot(Eigen::Vector3d(p.x(), p.y(), 0)), -1.0, 1e-14);
    }
}

TEST(Validation, MalformedInputsRaiseClearErrors) {
  const Eigen::MatrixXd c = Eigen::MatrixXd::Ones(1, 4);
  auto message = [](auto&& make) -> std::string {
    try {
      make();
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_NE(message([&] { BSpline(3, {0, 0, 0, 0, 1, 1, 0.5, 1}, c); }).find("non-decreasing"),
            std::string::npos);
  EXPECT_NE(message([&] { BSpline(3, {0, 0, 0, 0, 1, 1, 1}, c); }).find("7 knots"),
            std::string::npos);
  EXPECT_NE(message([&] { BSpline(3, {0, 0, 0, 0, NAN, 1, 1, 1}, c); }).find("not finite"),
            std::string::npos);
  EXPECT_NE(message([&] { BSpline(3, {0, 0, 0, 0, 1, 1, 1, 1}, c * NAN); }).find("not finite"),
            std::string::npos);
  EXPECT_NE(message([&] { BSpline(-1, {0, 1}, c); }).find("degree"), std::string::npos);
  EXPECT_NE(message([&] { NurbsCurve2d(1, {0, 0, 1, 1}, {{0, 0}, {1, 0}}, {1, 0}); })
                .find("weights must be > 0"),
            std::string::npos);
  EXPECT_NE(message([&] { NurbsCurve2d(1, {0, 0, 1, 1}, {{0, 0}, {1, 0}}, {1}); }).find("1 weights"),
            std::string::npos);
  EXPECT_NE(message([&] {
              NurbsSurface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
            }).find("expected 2 x 2"),
            std::string::npos);
}

}  // namespace
}  // namespace polarform
