// Knot insertion (A5.1) and refinement (A5.4): the geometry stays put (dense sampling, rational
// curves and surfaces, clamped and unclamped knot vectors), the knot vector gains exactly the
// inserted values, and malformed requests raise InputError.
#include "src/nurbs/knot_insertion.h"

#include <gtest/gtest.h>

#include "src/error.h"
#include "src/nurbs/knot_refinement.h"
#include "src/nurbs/periodic.h"
#include "tests/src/nurbs/kernel_test_support.h"

namespace polarform {
namespace {

using test::max_deviation;

Knots with_inserted(Knots U, double u, int times) {
  U.insert(std::upper_bound(U.begin(), U.end(), u), times, u);
  return U;
}

TEST(KnotInsertion, RationalCurvesKeepTheirGeometry) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> t(0.0, 3.0);
  double worst = 0.0;
  for (int p = 1; p <= 6; ++p) {
    for (int trial = 0; trial < 10; ++trial) {
      const BSpline c =
          test::random_rational(rng, p, test::random_knots(rng, p, 0.0, 3.0, 5, p - 1), 3);
      // A fresh value and an existing knot (raised to the degree).
      const double fresh = t(rng);
      const int times = 1 + trial % p;
      const BSpline a = insert_knot(c, fresh, times);
      EXPECT_EQ(a.knots(), with_inserted(c.knots(), fresh, times));
      worst = std::max(worst, max_deviation(c, a, 400, true));
      const double existing = c.knots()[p + 1];
      const int room = p - multiplicity(c.knots(), existing);
      if (room > 0) {
        const BSpline b = insert_knot(c, existing, room);
        EXPECT_EQ(multiplicity(b.knots(), existing), p);
        worst = std::max(worst, max_deviation(c, b, 400, true));
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_deviation", test::sci(worst));
}

TEST(KnotInsertion, UnclampedDomainEnds) {
  std::mt19937 rng(12);
  const int p = 3;
  const BSpline c =
      periodic_bspline(p, {0.0, 0.7, 1.5, 2.0, 3.1, 4.0}, test::random_coefs(rng, 2, 5));
  for (double u : {c.front(), c.back(), 0.7, 2.5}) {
    const BSpline a = insert_knot(c, u, p - multiplicity(c.knots(), u));
    EXPECT_EQ(multiplicity(a.knots(), u), p);
    EXPECT_LT(max_deviation(c, a, 400, false), 1e-12) << "u = " << u;
  }
}

TEST(KnotRefinement, RationalCurvesKeepTheirGeometry) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> t(0.0, 3.0);
  double worst = 0.0;
  for (int p = 1; p <= 7; ++p) {
    const BSpline c = test::random_rational(rng, p, test::random_knots(rng, p, 0.0, 3.0, 6, p), 2);
    std::vector<double> X;
    for (int i = 0; i < 25; ++i) X.push_back(t(rng));
    X.push_back(c.knots()[p + 1]);  // an existing knot, if room
    X.push_back(0.0 + 1e-9);
    std::sort(X.begin(), X.end());
    std::vector<double> allowed;
    for (double x : X)
      if (multiplicity(c.knots(), x) + std::count(allowed.begin(), allowed.end(), x) < p)
        allowed.push_back(x);
    const BSpline r = refine_knots(c, allowed);
    Knots expected = c.knots();
    expected.insert(expected.end(), allowed.begin(), allowed.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(r.knots(), expected);
    worst = std::max(worst, max_deviation(c, r, 1000, true));
    // The same as inserting one knot at a time.
    BSpline one_by_one = c;
    for (double x : allowed) one_by_one = insert_knot(one_by_one, x, 1);
    EXPECT_LT((one_by_one.coefs() - r.coefs()).cwiseAbs().maxCoeff(), 1e-12);
  }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_deviation", test::sci(worst));
}

TEST(KnotInsertion, RationalSurfaceBothDirections) {
  std::mt19937 rng(14);
  const Knots U = test::random_knots(rng, 3, 0.0, 1.0, 3, 2),
              V = test::random_knots(rng, 2, -1.0, 2.0, 4, 2);
  const int nu = static_cast<int>(U.size()) - 4, nv = static_cast<int>(V.size()) - 3;
  Eigen::MatrixXd h = test::random_coefs(rng, 4, nu * nv);
  h.row(3) = test::random_coefs(rng, 1, nu * nv, 0.5, 2.0);
  const NurbsSurface s(BSplineSurface(3, 2, U, V, h));
  const NurbsSurface a(insert_knot_v(insert_knot_u(s.homogeneous(), 0.37, 2), 0.5, 1));
  const NurbsSurface b(
      refine_knots_v(refine_knots_u(s.homogeneous(), {0.1, 0.2, 0.2, 0.9}), {-0.5, 0.0, 1.7}));
  EXPECT_EQ(a.size_u(), s.size_u() + 2);
  EXPECT_EQ(a.size_v(), s.size_v() + 1);
  EXPECT_EQ(b.size_u(), s.size_u() + 4);
  EXPECT_EQ(b.size_v(), s.size_v() + 3);
  double worst = 0.0;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j <= 60; ++j) {
      const double u = i / 60.0, v = -1.0 + 3.0 * j / 60.0;
      worst = std::max({worst, (s(u, v) - a(u, v)).norm(), (s(u, v) - b(u, v)).norm()});
    }
  EXPECT_LT(worst, 1e-12);
}

TEST(KnotInsertion, MalformedRequestsRaiseInputError) {
  std::mt19937 rng(15);
  const BSpline c = test::random_bspline(rng, 3, {0, 0, 0, 0, 1, 1, 2, 2, 2, 2}, 2);
  auto message = [&](auto&& call) {
    try {
      call();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no InputError");
  };
  EXPECT_NE(message([&] { insert_knot(c, 1.0, 2); }).find("multiplicity 4 > degree 3"),
            std::string::npos);
  EXPECT_NE(message([&] { insert_knot(c, 2.5, 1); }).find("outside the domain [0, 2]"),
            std::string::npos);
  EXPECT_NE(message([&] { insert_knot(c, 0.5, -1); }).find("times"), std::string::npos);
  EXPECT_NE(message([&] { refine_knots(c, {0.5, 0.25}); }).find("not sorted"), std::string::npos);
  EXPECT_NE(message([&] { refine_knots(c, {-0.1}); }).find("outside the domain"),
            std::string::npos);
  EXPECT_NE(message([&] {
              refine_knots(c, {0.5, 0.5, 0.5, 0.5});
            }).find("multiplicity 4"),
            std::string::npos);
  EXPECT_NE(message([&] { refine_knots(c, {2.0}); }).find("multiplicity 5"), std::string::npos);
}

}  // namespace
}  // namespace polarform
