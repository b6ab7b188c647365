// Degree elevation (A5.9): the geometry stays put (rational curves and surfaces, unclamped input),
// the knot vector gains t copies of every distinct value, and bad requests raise InputError.
#include "src/nurbs/degree_elevation.h"

#include <gtest/gtest.h>

#include "src/error.h"
#include "src/nurbs/periodic.h"
#include "tests/src/nurbs/kernel_test_support.h"

namespace polarform {
namespace {

using test::max_deviation;

Knots raised(const Knots& U, int t) {
  Knots out;
  for (const Breakpoint& b : breakpoints(U)) out.insert(out.end(), b.multiplicity + t, b.value);
  return out;
}

TEST(DegreeElevation, RationalCurvesKeepTheirGeometry) {
  std::mt19937 rng(41);
  double worst = 0.0;
  for (int p = 1; p <= 7; ++p)
    for (int t = 1; t <= 4; ++t) {
      const BSpline c =
          test::random_rational(rng, p, test::random_knots(rng, p, 0.0, 5.0, 6, p), 3);
      const BSpline e = elevate_degree(c, t);
      EXPECT_EQ(e.degree(), p + t);
      EXPECT_EQ(e.knots(), raised(c.knots(), t));
      worst = std::max(worst, max_deviation(c, e, 800, true));
    }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_deviation", test::sci(worst));
}

// Knots 1e-2 .. 1e-8 apart: the book's A5.9 loses up to all digits here (its knot removal runs
// one way), the decomposition-product-removal route stays at round-off.
TEST(DegreeElevation, NearlyCoincidentKnots) {
  std::mt19937 rng(43);
  double worst = 0.0;
  for (int p : {3, 5, 7})
    for (double gap : {1e-2, 1e-4, 1e-6, 1e-8}) {
      const Knots U = clamped_knots(p, 0, 3, {0.5, 1.0, 1.0 + gap, 2.0, 2.0 + gap, 2.0 + 2 * gap});
      const BSpline c = test::random_rational(rng, p, U, 2);
      const BSpline e = elevate_degree(c, 2);
      EXPECT_EQ(e.knots(), raised(U, 2));
      worst = std::max(worst, max_deviation(c, e, 3000, true));
    }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_deviation", test::sci(worst));
}

TEST(DegreeElevation, ConstantsAndUnclampedInput) {
  const BSpline k(0, {1.0, 4.0}, Eigen::MatrixXd::Constant(2, 1, 0.75));
  const BSpline e = elevate_degree(k, 3);
  EXPECT_EQ(e.knots(), (Knots{1, 1, 1, 1, 4, 4, 4, 4}));
  EXPECT_TRUE((e.coefs().array() == 0.75).all());

  std::mt19937 rng(42);
  const BSpline c = periodic_bspline(3, {0.0, 1.0, 1.5, 2.5, 4.0}, test::random_coefs(rng, 2, 4));
  const BSpline u = elevate_degree(c, 2);
  EXPECT_EQ(u.degree(), 5);
  EXPECT_EQ(u.front(), 0.0);
  EXPECT_EQ(u.back(), 4.0);
  EXPECT_LT(max_deviation(c, u, 800, false), 1e-12);
}

TEST(DegreeElevation, RationalSurface) {
  const NurbsSurface s = test::base_sphere();
  const NurbsSurface e(elevate_degree_v(elevate_degree_u(s.homogeneous(), 2), 1));
  EXPECT_EQ(e.degree_u(), 4);
  EXPECT_EQ(e.degree_v(), 3);
  double worst = 0.0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const double u = -1.5 + 3.0 * i / 40, v = 6.0 * j / 40;
      worst = std::max({worst, (e(u, v) - s(u, v)).norm(), std::abs(e(u, v).norm() - 1.0)});
    }
  EXPECT_LT(worst, 1e-12);
}

TEST(DegreeElevation, BadRequestsRaiseInputError) {
  const BSpline c(2, {0, 0, 0, 1, 1, 1, 2, 2, 2}, Eigen::MatrixXd::Zero(1, 6));
  EXPECT_THROW(elevate_degree(c, 1), InputError);  // knot 1 has multiplicity 3 > 2
  const BSpline d(2, {0, 0, 0, 2, 2, 2}, Eigen::MatrixXd::Zero(1, 3));
  EXPECT_THROW(elevate_degree(d, -1), InputError);
  EXPECT_THROW(elevate_degree(d, kMaxDegree), InputError);
}

}  // namespace
}  // namespace polarform
