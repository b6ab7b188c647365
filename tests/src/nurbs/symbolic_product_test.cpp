// The symbolic product (Bae 2002, Appendix A.1/A.2/B.1): equal to the pointwise product at random
// parameters for F of degree 0..7 times G of degree 2 and 4 with knots of every multiplicity, the
// knot vector equal to (A.7), bivariate products likewise, and malformed factors rejected.
#include "src/nurbs/symbolic_product.h"

#include <gtest/gtest.h>

#include <array>
#include <map>

#include "src/error.h"
#include "tests/src/nurbs/kernel_test_support.h"

namespace polarform {
namespace {

// (A.7) written out independently: per distinct interior value the larger of m_F + q and m_G + p,
// at most p + q; ends p + q + 1.
Knots expected_product_knots(int p, const Knots& U, int q, const Knots& V) {
  std::map<double, std::pair<int, int>> m;  // value -> (m_F, m_G)
  for (double u : U) ++m[u].first;
  for (double v : V) ++m[v].second;
  Knots out;
  for (auto [value, mm] : m) {
    int mult;
    if (value == U.front() || value == U.back()) {
      mult = p + q + 1;
    } else {
      mult = std::max(mm.first > 0 ? mm.first + q : 0, mm.second > 0 ? mm.second + p : 0);
      mult = std::min(mult, p + q);
    }
    out.insert(out.end(), mult, value);
  }
  return out;
}

TEST(SymbolicProduct, KnotVectorClosedForm) {
  // Knot 1 only in F (m 1 + q 3 = 4); knot 2 in both (max(2 + 3, 1 + 2) = 5).
  EXPECT_EQ(product_knots(2, {0, 0, 0, 1, 2, 2, 3, 3, 3}, 3, {0, 0, 0, 0, 2, 3, 3, 3, 3}),
            (Knots{0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3}));
  // A constant (degree 0) leaves the other factor's knots as they are.
  EXPECT_EQ(product_knots(0, {0, 4}, 2, {0, 0, 0, 1, 1, 4, 4, 4}), (Knots{0, 0, 0, 1, 1, 4, 4, 4}));
}

TEST(SymbolicProduct, MatchesThePointwiseProduct) {
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> t(0.0, 3.0);
  double worst = 0.0;
  for (int q : {2, 4}) {
    for (int p = 0; p <= 7; ++p) {
      // Shared knots: in both, with random multiplicities within each degree.
      const std::vector<double> shared{0.8, 2.1};
      const Knots V = test::random_knots(rng, q, 0.0, 3.0, 3, q, shared, 1 + p % q);
      const Knots U =
          p == 0 ? Knots{0.0, 3.0} : test::random_knots(rng, p, 0.0, 3.0, 4, p, shared, p);
      const BSpline f = test::random_bspline(rng, p, U, 1);
      const BSpline g = test::random_bspline(rng, q, V, 3);
      const BSpline h = product(f, g);
      EXPECT_EQ(h.degree(), p + q);
      EXPECT_EQ(h.knots(), expected_product_knots(p, U, q, V)) << "p = " << p << ", q = " << q;
      EXPECT_EQ(h.knots(), product_knots(p, U, q, V));
      const double scale = f.coefs().cwiseAbs().maxCoeff() * g.coefs().cwiseAbs().maxCoeff();
      double err = 0.0;
      for (int k = 0; k < 10000; ++k) {
        const double u = t(rng);
        err = std::max(err, (h.point(u) - f.point(u)(0) * g.point(u)).norm());
      }
      worst = std::max(worst, err / scale);
      // Row by row (dim f == dim g) against the same pointwise products.
      const BSpline f3 = test::random_bspline(rng, p, U, 3);
      const BSpline h3 = product(f3, g);
      for (int k = 0; k < 1000; ++k) {
        const double u = t(rng);
        const double s3 = f3.coefs().cwiseAbs().maxCoeff() * g.coefs().cwiseAbs().maxCoeff();
        worst = std::max(worst, (h3.point(u) - f3.point(u).cwiseProduct(g.point(u))).norm() / s3);
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_relative_error", test::sci(worst));
}

// Knots of F a hair away from the circle's arc joints: the exact removal must stay at round-off
// (the symmetric split of the book's A5.8 loses up to 1e-5 here and refuses the removal).
TEST(SymbolicProduct, NearlyCoincidentKnotsStayExact) {
  std::mt19937 rng(64);
  std::uniform_real_distribution<double> t(0.0, 2 * std::numbers::pi);
  const double q = std::numbers::pi / 2;
  const BSpline circle(2, test::rqb_circle_knots(), test::rqb_circle_coefs(1.0));
  double worst = 0.0;
  for (int p : {3, 5, 7}) {
    for (double gap : {1e-3, 1e-6, 1e-10}) {
      const Knots U = clamped_knots(p, 0.0, 4 * q, {0.3, q + gap, 2.0, 2.0, 3 * q - gap, 5.0});
      const BSpline f = test::random_bspline(rng, p, U, 1);
      const BSpline h = product(f, circle);
      EXPECT_EQ(h.knots(), expected_product_knots(p, U, 2, circle.knots()));
      for (int k = 0; k < 2000; ++k) {
        const double u = t(rng);
        worst = std::max(worst, (h.point(u) - f.point(u)(0) * circle.point(u)).norm() /
                                    f.coefs().cwiseAbs().maxCoeff());
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_relative_error", test::sci(worst));
}

// A factor knot an ulp off the circle's joint (a uniform F whose span ends are computed, not the
// joint itself) is snapped onto it: no second break an ulp away (it made knots of multiplicity
// 3 + 5 that the curve's reversal merged into 8 > degree + 1); the product still equals f·g.
TEST(SymbolicProduct, KnotsAnUlpOffABreakAreSnappedOntoIt) {
  std::mt19937 rng(65);
  const double q = std::numbers::pi / 2;
  const BSpline circle(2, test::rqb_circle_knots(), test::rqb_circle_coefs(1.0));
  const double off = std::nextafter(3 * q, 10.0);
  ASSERT_NE(off, 3 * q);
  EXPECT_EQ(snap_knots({0, 0, off, 7}, circle.knots())[2], 3 * q);
  EXPECT_EQ(snap_knots({0, 0, 3 * q + 1e-9, 7}, circle.knots())[2], 3 * q + 1e-9);  // real gap
  const Knots U = clamped_knots(3, 0.0, 4 * q, {0.3, std::nextafter(q, 0.0), off, 5.0});
  const BSpline f = test::random_bspline(rng, 3, U, 1);
  const BSpline h = product(f, circle);
  for (const Breakpoint& b : breakpoints(h.knots())) EXPECT_LE(b.multiplicity, h.degree() + 1);
  EXPECT_EQ(multiplicity(h.knots(), 3 * q), 5);  // max(1 + 2, 2 + 3)
  EXPECT_EQ(multiplicity(h.knots(), off), 0);
  double worst = 0.0;
  for (int k = 0; k <= 2000; ++k) {
    const double u = 4 * q * k / 2000;
    worst = std::max(worst, (h.point(u) - f.point(u)(0) * circle.point(u)).norm());
  }
  EXPECT_LT(worst, 1e-12 * f.coefs().cwiseAbs().maxCoeff());
}

TEST(SymbolicProduct, RowMapsAndOptionalRemoval) {
  std::mt19937 rng(62);
  const BSpline f = test::random_bspline(rng, 3, test::random_knots(rng, 3, 0.0, 1.0, 3, 2), 2);
  const BSpline g = test::random_bspline(rng, 2, test::random_knots(rng, 2, 0.0, 1.0, 2, 1), 3);
  const BSpline h = product_rows(f, {1, 0, 0, 1}, g, {2, 2, 0, 1});
  ASSERT_EQ(h.dim(), 4);
  for (double u : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    const Eigen::VectorXd a = f.point(u), b = g.point(u), c = h.point(u);
    EXPECT_NEAR(c(0), a(1) * b(2), 1e-13);
    EXPECT_NEAR(c(1), a(0) * b(2), 1e-13);
    EXPECT_NEAR(c(2), a(0) * b(0), 1e-13);
    EXPECT_NEAR(c(3), a(1) * b(1), 1e-13);
  }
  // x·x with x(u) = u written with a removable knot at 0.5: (A.7) keeps that knot twice (C0 at
  // degree 2), removal_tol drops it and leaves u² as a Bezier quadratic (0, 0, 1).
  const BSpline x(1, {0, 0, 0.5, 1, 1}, (Eigen::MatrixXd(1, 3) << 0, 0.5, 1).finished());
  EXPECT_EQ(product(x, x).knots(), (Knots{0, 0, 0, 0.5, 0.5, 1, 1, 1}));
  const BSpline sq = product(x, x, 1e-12);
  EXPECT_EQ(sq.knots(), (Knots{0, 0, 0, 1, 1, 1}));
  EXPECT_NEAR(sq.coefs()(0, 0), 0.0, 1e-15);
  EXPECT_NEAR(sq.coefs()(0, 1), 0.0, 1e-15);
  EXPECT_NEAR(sq.coefs()(0, 2), 1.0, 1e-15);
}

TEST(SymbolicProduct, BivariateMatchesThePointwiseProduct) {
  std::mt19937 rng(63);
  std::uniform_real_distribution<double> t(0.0, 1.0);
  double worst = 0.0;
  for (auto [pu, pv, qu, qv] :
       {std::array{3, 2, 2, 2}, std::array{0, 4, 1, 2}, std::array{5, 1, 2, 0}}) {
    const Knots Uf =
        pu == 0 ? Knots{0.0, 1.0} : test::random_knots(rng, pu, 0.0, 1.0, 2, pu, {0.5}, 1);
    const Knots Vf =
        pv == 0 ? Knots{0.0, 2.0} : test::random_knots(rng, pv, 0.0, 2.0, 2, pv, {1.0}, 1);
    const Knots Ug =
        qu == 0 ? Knots{0.0, 1.0} : test::random_knots(rng, qu, 0.0, 1.0, 1, qu, {0.5}, qu);
    const Knots Vg = qv == 0 ? Knots{0.0, 2.0} : test::random_knots(rng, qv, 0.0, 2.0, 2, qv);
    auto count = [](int d, const Knots& K) { return static_cast<int>(K.size()) - d - 1; };
    const BSplineSurface f(pu, pv, Uf, Vf,
                           test::random_coefs(rng, 1, count(pu, Uf) * count(pv, Vf)));
    const BSplineSurface g(qu, qv, Ug, Vg,
                           test::random_coefs(rng, 2, count(qu, Ug) * count(qv, Vg)));
    const BSplineSurface h = product(f, g);
    EXPECT_EQ(h.degree_u(), pu + qu);
    EXPECT_EQ(h.degree_v(), pv + qv);
    EXPECT_EQ(h.knots_u(), expected_product_knots(pu, Uf, qu, Ug));
    EXPECT_EQ(h.knots_v(), expected_product_knots(pv, Vf, qv, Vg));
    const double scale = f.coefs().cwiseAbs().maxCoeff() * g.coefs().cwiseAbs().maxCoeff();
    for (int k = 0; k < 3000; ++k) {
      const double u = t(rng), v = 2.0 * t(rng);
      worst = std::max(worst, (h.point(u, v) - f.point(u, v)(0) * g.point(u, v)).norm() / scale);
    }
  }
  EXPECT_LT(worst, 1e-12);
  RecordProperty("max_relative_error", test::sci(worst));
}

TEST(SymbolicProduct, MalformedFactorsRaiseInputError) {
  const BSpline f(2, {0, 0, 0, 1, 1, 1}, Eigen::MatrixXd::Ones(1, 3));
  const BSpline g(2, {0, 0, 0, 2, 2, 2}, Eigen::MatrixXd::Ones(2, 3));
  try {
    product(f, g);
    ADD_FAILURE() << "mismatched domains accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("domains differ: [0, 1] and [0, 2]"), std::string::npos)
        << e.what();
  }
  const BSpline g3(2, {0, 0, 0, 1, 1, 1}, Eigen::MatrixXd::Ones(3, 3));
  const BSpline f2(2, {0, 0, 0, 1, 1, 1}, Eigen::MatrixXd::Ones(2, 3));
  EXPECT_THROW(product(f2, g3), InputError);                        // dimension 2 vs 3
  EXPECT_THROW(product_rows(f2, {0, 2}, g3, {0, 1}), InputError);   // row 2 of a 2-row factor
  EXPECT_THROW(product_rows(f2, {0}, g3, {0, 1}), InputError);      // lengths differ
  const BSpline step(0, {0, 0.5, 1}, Eigen::MatrixXd::Ones(1, 2));  // discontinuous
  EXPECT_THROW(product(step, g3), InputError);
  EXPECT_THROW(product(f, g3, -1.0), InputError);
}

}  // namespace
}  // namespace polarform
