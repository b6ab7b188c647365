// Knot removal (A5.8): every knot a previous insertion added comes out again (count, knot vector
// and geometry), a knot that is not removable within tol stays, eq. (5.30) has its closed form,
// and malformed requests raise InputError.
#include "src/nurbs/knot_removal.h"

#include <gtest/gtest.h>

#include "src/error.h"
#include "src/nurbs/knot_insertion.h"
#include "src/nurbs/knot_refinement.h"
#include "tests/src/nurbs/kernel_test_support.h"

namespace polarform {
namespace {

using test::max_deviation;

TEST(KnotRemoval, RemovesWhatInsertionAdded) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> t(0.0, 2.0);
  double worst = 0.0;
  for (int p = 1; p <= 7; ++p) {
    for (int trial = 0; trial < 6; ++trial) {
      const BSpline c =
          test::random_rational(rng, p, test::random_knots(rng, p, 0.0, 2.0, 4, p - 1), 2);
      // remove_knot undoes a single insertion exactly `times` times.
      const double u = t(rng);
      const int times = 1 + (trial % p);
      const KnotRemoval r = remove_knot(insert_knot(c, u, times), u, times, 1e-12);
      ASSERT_EQ(r.removed, times);
      ASSERT_EQ(r.spline.knots(), c.knots());
      worst = std::max(worst, (r.spline.coefs() - c.coefs()).cwiseAbs().maxCoeff());
      // remove_removable_knots undoes a whole refinement (new values and raised old ones).
      std::vector<double> X;
      for (int i = 0; i < 6; ++i) X.insert(X.end(), 1 + i % p, t(rng));
      for (const Breakpoint& b : breakpoints(c.knots()))
        if (b.value > 0.0 && b.value < 2.0 && b.multiplicity < p) X.push_back(b.value);
      std::sort(X.begin(), X.end());
      const BSpline refined = refine_knots(c, X);
      const BSpline back = remove_removable_knots(refined, 1e-10);
      ASSERT_EQ(back.knots(), c.knots()) << "p = " << p << ", trial " << trial;
      worst = std::max(worst, (back.coefs() - c.coefs()).cwiseAbs().maxCoeff());
      worst = std::max(worst, max_deviation(c, back, 500, true));
    }
  }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_deviation", test::sci(worst));
}

// Inserted knots 1e-7 and 1e-9 from a knot of full multiplicity come out exactly, at a tolerance
// (1e-13) far below what moving a knot by the gap would cost; the book's symmetric split amplifies
// round-off by about the inverse gap here and refuses them.
TEST(KnotRemoval, NextToNearlyCoincidentKnots) {
  std::mt19937 rng(25);
  double worst = 0.0;
  for (int p = 2; p <= 7; ++p) {
    const BSpline c = test::random_rational(rng, p, clamped_knots(p, 0.0, 2.0, Knots(p, 1.0)), 2);
    const BSpline r = refine_knots(c, {1.0 - 1e-7, 1.0 + 1e-9, 1.0 + 1e-9});
    const BSpline back = remove_removable_knots(r, 1e-13);
    ASSERT_EQ(back.knots(), c.knots()) << "p = " << p;
    worst = std::max(worst, (back.coefs() - c.coefs()).cwiseAbs().maxCoeff());
  }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_coefficient_error", test::sci(worst));
}

TEST(KnotRemoval, RefusesAKnotThatIsNotRemovable) {
  std::mt19937 rng(22);
  const BSpline c = test::random_bspline(rng, 3, {0, 0, 0, 0, 0.5, 1, 1, 1.5, 2, 2, 2, 2}, 2);
  for (double u : {0.5, 1.0, 1.5}) {
    const KnotRemoval r = remove_knot(c, u, multiplicity(c.knots(), u), 1e-3);
    EXPECT_EQ(r.removed, 0) << "u = " << u;
    EXPECT_EQ(r.spline, c);
  }
  // With a tolerance above the deviation the same knot goes and the curve moves by about that.
  const KnotRemoval loose = remove_knot(c, 0.5, 1, 10.0);
  EXPECT_EQ(loose.removed, 1);
  EXPECT_GT(max_deviation(c, loose.spline, 200, false), 1e-3);
  EXPECT_EQ(remove_removable_knots(c, 1e-3), c);
}

TEST(KnotRemoval, SurfaceRemovesWhatInsertionAdded) {
  std::mt19937 rng(23);
  const Knots U = test::random_knots(rng, 3, 0.0, 1.0, 3, 2),
              V = test::random_knots(rng, 2, 0.0, 2.0, 3, 1);
  const int nu = static_cast<int>(U.size()) - 4, nv = static_cast<int>(V.size()) - 3;
  const BSplineSurface s(3, 2, U, V, test::random_coefs(rng, 3, nu * nv));
  const BSplineSurface r = refine_knots_v(refine_knots_u(s, {0.2, 0.2, 0.6}), {0.3, 1.1});
  const SurfaceKnotRemoval one = remove_knot_u(r, 0.2, 2, 1e-12);
  EXPECT_EQ(one.removed, 2);
  EXPECT_LT(max_deviation(s, one.surface, 40), 1e-12);
  const BSplineSurface back = remove_removable_knots_v(remove_removable_knots_u(r, 1e-10), 1e-10);
  EXPECT_EQ(back.knots_u(), s.knots_u());
  EXPECT_EQ(back.knots_v(), s.knots_v());
  EXPECT_LT((back.coefs() - s.coefs()).cwiseAbs().maxCoeff(), 1e-12);
  // The v knot 1.1 alone, through remove_knot_v.
  const SurfaceKnotRemoval v = remove_knot_v(refine_knots_v(s, {1.1}), 1.1, 1, 1e-12);
  EXPECT_EQ(v.removed, 1);
  EXPECT_EQ(v.surface.knots_v(), s.knots_v());
}

TEST(KnotRemoval, HomogeneousToleranceClosedForm) {
  // Points (3, 4) with weight 2 and (0, 1) with weight 0.5: w_min = 0.5, |P|max = 5.
  const BSpline h(1, {0, 0, 1, 1}, (Eigen::MatrixXd(3, 2) << 6, 0, 8, 0.5, 2, 0.5).finished());
  EXPECT_DOUBLE_EQ(homogeneous_tolerance(h, 0.012), 0.012 * 0.5 / 6.0);
  EXPECT_THROW(homogeneous_tolerance(h, -1.0), InputError);
  const BSpline bad(1, {0, 0, 1, 1}, (Eigen::MatrixXd(2, 2) << 1, 1, 1, -1).finished());
  EXPECT_THROW(homogeneous_tolerance(bad, 0.1), InputError);
}

TEST(KnotRemoval, MalformedRequestsRaiseInputError) {
  std::mt19937 rng(24);
  const BSpline c = test::random_bspline(rng, 2, {0, 0, 0, 1, 1, 2, 2, 2}, 1);
  EXPECT_THROW(remove_knot(c, 0.5, 1, 1e-9), InputError);  // not a knot
  EXPECT_THROW(remove_knot(c, 0.0, 1, 1e-9), InputError);  // domain end
  EXPECT_THROW(remove_knot(c, 1.0, 3, 1e-9), InputError);  // more than its multiplicity
  EXPECT_THROW(remove_knot(c, 1.0, 1, -1.0), InputError);  // negative tolerance
  try {
    remove_knot(c, 0.5, 1, 1e-9);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("0.5 is not a knot"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace polarform
