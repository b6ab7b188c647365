// common_basis: B-splines of different degrees and knots rewritten as the rows of one B-spline on
// the highest degree and the union of the (elevated) knots, each row unchanged pointwise.
#include "src/nurbs/common_basis.h"

#include <gtest/gtest.h>

#include "src/error.h"
#include "src/nurbs/periodic.h"
#include "tests/src/nurbs/kernel_test_support.h"

namespace polarform {
namespace {

TEST(CommonBasis, CurvesKeepTheirValues) {
  std::mt19937 rng(81);
  const BSpline a = test::random_bspline(rng, 2, {0, 0, 0, 1, 1, 2.5, 3, 3, 3}, 2);
  const BSpline b = test::random_bspline(rng, 3, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3}, 1);
  const BSpline k(0, {0.0, 3.0}, Eigen::MatrixXd::Constant(1, 1, 4.0));
  const BSpline c = periodic_bspline(2, {0.0, 0.5, 2.0, 3.0}, test::random_coefs(rng, 1, 3));
  const BSpline all = common_basis({a, b, k, c});
  ASSERT_EQ(all.dim(), 5);
  EXPECT_EQ(all.degree(), 3);
  // a's knots raised by 1 (1 twice -> 3, 2.5 once -> 2), b's as they are, c's clamped and raised.
  EXPECT_EQ(all.knots(), (Knots{0, 0, 0, 0, 0.5, 0.5, 1, 1, 1, 2, 2, 2.5, 2.5, 3, 3, 3, 3}));
  double worst = 0.0;
  for (int i = 0; i <= 600; ++i) {
    const double u = 3.0 * i / 600;
    const Eigen::VectorXd h = all.point(u);
    worst = std::max({worst, (h.head(2) - a.point(u)).norm(), std::abs(h(2) - b.point(u)(0)),
                      std::abs(h(3) - 4.0), std::abs(h(4) - c.point(u)(0))});
  }
  EXPECT_LT(worst, 1e-13);
  EXPECT_THROW(common_basis({a, BSpline(1, {0, 0, 2, 2}, Eigen::MatrixXd::Zero(1, 2))}),
               InputError);
  EXPECT_THROW(common_basis(std::vector<BSpline>{}), InputError);
}

TEST(CommonBasis, SurfacesKeepTheirValues) {
  std::mt19937 rng(82);
  const BSplineSurface a(2, 1, {0, 0, 0, 0.5, 1, 1, 1}, {0, 0, 2, 2},
                         test::random_coefs(rng, 1, 8));
  const BSplineSurface b(1, 3, {0, 0, 0.25, 1, 1}, {0, 0, 0, 0, 1, 2, 2, 2, 2},
                         test::random_coefs(rng, 2, 15));
  const BSplineSurface all = common_basis({a, b});
  EXPECT_EQ(all.degree_u(), 2);
  EXPECT_EQ(all.degree_v(), 3);
  EXPECT_EQ(all.knots_u(), (Knots{0, 0, 0, 0.25, 0.25, 0.5, 1, 1, 1}));
  EXPECT_EQ(all.knots_v(), (Knots{0, 0, 0, 0, 1, 2, 2, 2, 2}));
  double worst = 0.0;
  for (int i = 0; i <= 30; ++i)
    for (int j = 0; j <= 30; ++j) {
      const double u = i / 30.0, v = 2.0 * j / 30.0;
      const Eigen::VectorXd h = all.point(u, v);
      worst =
          std::max({worst, std::abs(h(0) - a.point(u, v)(0)), (h.tail(2) - b.point(u, v)).norm()});
    }
  EXPECT_LT(worst, 1e-13);
}

}  // namespace
}  // namespace polarform
