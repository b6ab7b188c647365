// Geometric products (Bae 2002, eqs. (A.2), (B.2), (B.3)): F times an RQB or quartic (5.2) circle,
// a base sphere and a base cylinder equal the pointwise products, have the degrees of DESIGN §4.1,
// and a constant F gives the exact circle / sphere / cylinder without spurious elevation.
#include <gtest/gtest.h>

#include "src/error.h"
#include "src/nurbs/symbolic_product.h"
#include "tests/src/nurbs/kernel_test_support.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

// Quasi-uniform quartic circle of `arcs` equal arcs (Bae 2002, eq. (5.2), printed α), parameter =
// angle, interior knots of multiplicity 4 at the arc ends.
NurbsCurve2d quartic_circle(int arcs) {
  const double phi = kPi / arcs, w = std::cos(phi), c = std::cos(phi / 5);
  const double alpha = (4 - 2 * c * c * c + c) / (-1 + 8 * c * c * c - 4 * c);
  const double a2 = alpha * alpha, w2 = (a2 + a2 * w + w) / 3;
  Knots U(5, 0.0);
  Eigen::MatrixXd h(3, 4 * arcs + 1);
  for (int j = 0; j < arcs; ++j) {
    const double t0 = 2 * phi * j;
    const Eigen::Vector2d b0(std::cos(t0), std::sin(t0)),
        b2(std::cos(t0 + 2 * phi), std::sin(t0 + 2 * phi));
    const Eigen::Vector2d b1 = Eigen::Vector2d(std::cos(t0 + phi), std::sin(t0 + phi)) / w;
    const Eigen::Vector2d q[5] = {
        b0, (b0 + w * b1) / (1 + w),
        (a2 * b0 + 2 * w * (1 + a2) * b1 + a2 * b2) / (2 * (a2 + a2 * w + w)),
        (b2 + w * b1) / (1 + w), b2};
    const double wt[5] = {1, (1 + w) * alpha / 2, w2, (1 + w) * alpha / 2, 1};
    for (int i = 0; i < 5; ++i) h.col(4 * j + i) << wt[i] * q[i], wt[i];
    U.insert(U.end(), j + 1 < arcs ? 4 : 5, 2 * phi * (j + 1));
  }
  U.back() = 2 * kPi;
  std::fill(U.end() - 5, U.end(), 2 * kPi);
  return NurbsCurve2d(BSpline(4, U, h));
}

BSplineFunction positive_function(std::mt19937& rng, int p, double a, double b,
                                  const std::vector<double>& shared) {
  const Knots U = p == 0 ? Knots{a, b} : test::random_knots(rng, p, a, b, 5, p, shared, 1);
  return BSplineFunction(
      BSpline(p, U, test::random_coefs(rng, 1, static_cast<int>(U.size()) - p - 1, 1.0, 2.0)));
}

TEST(GeometricProduct, ConstantTimesRqbCircleStaysAnExactCircle) {
  const NurbsCurve2d circle = test::rqb_circle(1.0);
  const BSplineFunction F(0, {0.0, 2 * kPi}, Eigen::VectorXd::Constant(1, 2.5));
  const NurbsCurve2d C = product(F, circle);
  EXPECT_EQ(C.degree(), 2);
  EXPECT_EQ(C.knots(), circle.knots());
  double worst = 0.0;
  for (int k = 0; k <= 10000; ++k)
    worst = std::max(worst, std::abs(C(2 * kPi * k / 10000).norm() - 2.5) / 2.5);
  EXPECT_LT(worst, 1e-14);
  RecordProperty("max_relative_radius_error", test::sci(worst));
}

TEST(GeometricProduct, CurveEqualsPointwiseProduct) {
  std::mt19937 rng(71);
  std::uniform_real_distribution<double> t(0.0, 2 * kPi);
  const NurbsCurve2d rqb = test::rqb_circle(1.0), quartic = quartic_circle(6);
  for (int k = 0; k <= 1000; ++k) ASSERT_NEAR(quartic(2 * kPi * k / 1000).norm(), 1.0, 1e-14);
  const NurbsCurve3d space(
      test::random_rational(rng, 3, test::random_knots(rng, 3, 0.0, 2 * kPi, 4, 2), 3));
  double worst = 0.0;
  for (int p = 0; p <= 5; ++p) {
    const BSplineFunction F = positive_function(rng, p, 0.0, 2 * kPi, {kPi / 2, kPi});
    const NurbsCurve2d a = product(F, rqb), b = product(F, quartic);
    const NurbsCurve3d c = product(F, space);
    EXPECT_EQ(a.degree(), p + 2);
    EXPECT_EQ(b.degree(), p + 4);
    EXPECT_EQ(c.degree(), p + 3);
    EXPECT_EQ(a.knots(), product_knots(p, F.knots(), 2, rqb.knots()));
    for (int k = 0; k < 10000; ++k) {
      const double u = t(rng), f = F(u);
      worst =
          std::max({worst, (a(u) - f * rqb(u)).norm() / 2.0, (b(u) - f * quartic(u)).norm() / 2.0,
                    (c(u) - f * space(u)).norm() / (2.0 * std::max(1.0, space(u).norm()))});
    }
  }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_relative_error", test::sci(worst));
}

TEST(GeometricProduct, RemovalToleranceDropsWhatTheShapeDoesNotNeed) {
  // A constant F written as a cubic with interior knots: (A.7) keeps them (multiplicity 1 + 2);
  // a Cartesian removal tolerance drops them all, leaving the circle elevated to degree 5.
  const BSplineFunction F(3, {0, 0, 0, 0, 1, 2, 4, 4.5, 2 * kPi, 2 * kPi, 2 * kPi, 2 * kPi},
                          Eigen::VectorXd::Constant(8, 3.0));
  const NurbsCurve2d circle = test::rqb_circle(1.0);
  const NurbsCurve2d kept = product(F, circle), lean = product(F, circle, 1e-9);
  EXPECT_EQ(multiplicity(kept.knots(), 1.0), 3);
  EXPECT_EQ(multiplicity(lean.knots(), 1.0), 0);
  EXPECT_EQ(lean.size(), 4 * 5 + 1);  // four rational quintic arcs joined C0
  double worst = 0.0;
  for (int k = 0; k <= 2000; ++k)
    worst = std::max(worst, std::abs(lean(2 * kPi * k / 2000).norm() - 3.0));
  EXPECT_LT(worst, 1e-9);
}

TEST(GeometricProduct, SphericalEqualsPointwiseProduct) {
  std::mt19937 rng(72);
  std::uniform_real_distribution<double> t(0.0, 1.0);
  const NurbsSurface sphere = test::base_sphere();
  double worst = 0.0;
  for (auto [p, q] : {std::pair{0, 0}, std::pair{3, 2}, std::pair{1, 4}}) {
    const Knots U = p == 0 ? Knots{-kPi / 2, kPi / 2}
                           : test::random_knots(rng, p, -kPi / 2, kPi / 2, 2, p, {0.0}, 1);
    const Knots V =
        q == 0 ? Knots{0.0, 2 * kPi} : test::random_knots(rng, q, 0.0, 2 * kPi, 3, q, {kPi}, 2);
    const int n = (static_cast<int>(U.size()) - p - 1) * (static_cast<int>(V.size()) - q - 1);
    const BSplineSurface F(p, q, U, V, test::random_coefs(rng, 1, n, 1.0, 2.0));
    const NurbsSurface S = product(F, sphere);
    EXPECT_EQ(S.degree_u(), p + 2);
    EXPECT_EQ(S.degree_v(), q + 2);
    for (int k = 0; k < 4000; ++k) {
      const double u = -kPi / 2 + kPi * t(rng), v = 2 * kPi * t(rng);
      const double f = F.point(u, v)(0);
      worst = std::max(worst, (S(u, v) - f * sphere(u, v)).norm() / 2.0);
      if (p == 0 && q == 0) worst = std::max(worst, std::abs(S(u, v).norm() - f) / f);
    }
  }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_relative_error", test::sci(worst));
}

TEST(GeometricProduct, CylindricalEqualsPointwiseProduct) {
  std::mt19937 rng(73);
  std::uniform_real_distribution<double> t(0.0, 1.0);
  const NurbsSurface cylinder = test::base_cylinder(-1.0, 2.0);
  double worst = 0.0;
  for (auto [p, q] : {std::pair{0, 0}, std::pair{3, 0}, std::pair{2, 3}, std::pair{1, 1}}) {
    const Knots U =
        p == 0 ? Knots{-1.0, 2.0} : test::random_knots(rng, p, -1.0, 2.0, 2, p, {0.5}, 1);
    const Knots V =
        q == 0 ? Knots{0.0, 2 * kPi} : test::random_knots(rng, q, 0.0, 2 * kPi, 3, q, {kPi / 2}, 1);
    const int n = (static_cast<int>(U.size()) - p - 1) * (static_cast<int>(V.size()) - q - 1);
    const BSplineSurface F(p, q, U, V, test::random_coefs(rng, 1, n, 1.0, 2.0));
    const NurbsSurface S = cylindrical_product(F, cylinder);
    EXPECT_EQ(S.degree_u(), std::max(p, 1));
    EXPECT_EQ(S.degree_v(), q + 2);
    for (int k = 0; k < 4000; ++k) {
      const double u = -1.0 + 3.0 * t(rng), v = 2 * kPi * t(rng);
      const double f = F.point(u, v)(0);
      const Eigen::Vector3d b = cylinder(u, v);
      worst =
          std::max(worst, (S(u, v) - Eigen::Vector3d(f * b.x(), f * b.y(), b.z())).norm() / 2.0);
    }
  }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_relative_error", test::sci(worst));
}

TEST(GeometricProduct, MalformedInputRaisesInputError) {
  const BSplineSurface F(0, 0, {-kPi / 2, kPi / 2}, {0.0, 2 * kPi}, Eigen::MatrixXd::Ones(1, 1));
  EXPECT_THROW(cylindrical_product(F, test::base_sphere()), InputError);  // not a cylinder
  const BSplineSurface F2(0, 0, {-1.0, 2.0}, {0.0, 2 * kPi}, Eigen::MatrixXd::Ones(2, 1));
  EXPECT_THROW(cylindrical_product(F2, test::base_cylinder(-1.0, 2.0)), InputError);  // not scalar
  EXPECT_THROW(product(F, test::base_cylinder(-1.0, 2.0)), InputError);  // u-domains differ
  const BSplineFunction f(0, {0.0, 1.0}, Eigen::VectorXd::Ones(1));
  EXPECT_THROW(product(f, test::rqb_circle(1.0)), InputError);  // [0, 1] vs [0, 2π]
}

}  // namespace
}  // namespace polarform
