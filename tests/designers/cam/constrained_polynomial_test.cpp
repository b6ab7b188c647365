// Polynomial laws of a stated degree from constraints (constrained_polynomial.h): the 3-4-5 and
// 4-5-6-7 laws come out of their end constraints, a degree-7 law meets interior constraints, the
// peak factors from the derivative's roots equal the closed forms and a dense measurement, the
// least-jerk-energy solution of an under-determined law is the quintic, and wrong counts are
// errors that state them.
#include "designers/cam/constrained_polynomial.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "designers/cam/motion_law.h"
#include "designers/cam/motion_segment.h"
#include "src/error.h"
#include "tests/designers/cam/cam_test_support.h"

namespace polarform {
namespace {

// S(0) = 0, S(1) = 1 and derivatives 1..order zero at both ends.
std::vector<PolynomialConstraint> rest_to_rest(int order) {
  std::vector<PolynomialConstraint> c;
  for (int k = 0; k <= order; ++k) {
    c.push_back({0.0, k, 0.0});
    c.push_back({1.0, k, k == 0 ? 1.0 : 0.0});
  }
  return c;
}

double value(const Polynomial& p, double x, int k) {
  double o[8];
  p.derivatives(x, k, o);
  return o[k];
}

void expect_coefficients(const Polynomial& p, const std::vector<double>& expected, double tol) {
  for (std::size_t i = 0; i < expected.size() || i < p.coefficients().size(); ++i) {
    const double got = i < p.coefficients().size() ? p.coefficients()[i] : 0.0;
    const double want = i < expected.size() ? expected[i] : 0.0;
    EXPECT_NEAR(got, want, tol) << "coefficient of x^" << i;
  }
}

TEST(ConstrainedPolynomial, EndConstraintsGiveThe345And4567Laws) {
  const ConstrainedPolynomial p5 = constrained_polynomial(5, rest_to_rest(2));
  EXPECT_FALSE(p5.least_jerk_energy);
  expect_coefficients(p5.polynomial, {0, 0, 0, 10, -15, 6}, 1e-12);
  const ConstrainedPolynomial p7 = constrained_polynomial(7, rest_to_rest(3));
  expect_coefficients(p7.polynomial, {0, 0, 0, 0, 35, -84, 70, -20}, 1e-12);
  // The laws themselves, value and derivatives 1..4, to 1e-12 of each derivative's largest
  // magnitude on [0, 1] (the rounding floor of summing its terms).
  for (const auto& [law, solved] : {std::pair{MotionLaw::Polynomial345, p5.polynomial},
                                    std::pair{MotionLaw::Polynomial4567, p7.polynomial}}) {
    double scale[5] = {1, 1, 1, 1, 1};
    for (int i = 0; i <= 100; ++i) {
      double o[5];
      standard_law(law, i / 100.0, 4, o);
      for (int k = 0; k <= 4; ++k) scale[k] = std::max(scale[k], std::abs(o[k]));
    }
    for (int i = 0; i <= 100; ++i) {
      double o[5];
      standard_law(law, i / 100.0, 4, o);
      for (int k = 0; k <= 4; ++k)
        EXPECT_NEAR(value(solved, i / 100.0, k), o[k], 1e-12 * scale[k])
            << motion_law_name(law) << " S^(" << k << ") at " << i / 100.0;
    }
  }
  // Peak factors against DESIGN §4.5's closed forms (1e-9) and against the standard laws' (1e-12).
  const PolynomialPeaks a = polynomial_peaks(p5.polynomial), b = polynomial_peaks(p7.polynomial);
  EXPECT_NEAR(a.cv, 15.0 / 8, 1e-9);
  EXPECT_NEAR(a.ca, 10 / std::sqrt(3.0), 1e-9);
  EXPECT_NEAR(a.cj, 60, 1e-9 * 60);
  EXPECT_NEAR(b.cv, 35.0 / 16, 1e-9);
  EXPECT_NEAR(b.ca, 84 * std::sqrt(5.0) / 25, 1e-9);
  EXPECT_NEAR(b.cj, 52.5, 1e-9 * 52.5);
  const PolynomialPeaks sa = polynomial_peaks(*standard_law_polynomial(MotionLaw::Polynomial345));
  const PolynomialPeaks sb = polynomial_peaks(*standard_law_polynomial(MotionLaw::Polynomial4567));
  EXPECT_NEAR(a.cv, sa.cv, 1e-12);
  EXPECT_NEAR(a.ca, sa.ca, 1e-12);
  EXPECT_NEAR(a.cj, sa.cj, 1e-12 * 60);
  EXPECT_NEAR(b.cv, sb.cv, 1e-12);
  EXPECT_NEAR(b.ca, sb.ca, 1e-12);
  EXPECT_NEAR(b.cj, sb.cj, 1e-12 * 60);
}

// Degree 7: rest-to-rest in s, v, a (6) plus S(0.4) = 0.3 and S'(0.6) = 1.9 (8 = 7 + 1).
TEST(ConstrainedPolynomial, DegreeSevenMeetsInteriorConstraints) {
  std::vector<PolynomialConstraint> c = rest_to_rest(2);
  c.push_back({0.4, 0, 0.3});
  c.push_back({0.6, 1, 1.9});
  const ConstrainedPolynomial p = constrained_polynomial(7, c);
  EXPECT_EQ(p.polynomial.degree(), 7);
  EXPECT_FALSE(p.least_jerk_energy);
  for (const PolynomialConstraint& k : c)
    EXPECT_NEAR(value(p.polynomial, k.x, k.derivative), k.value, 1e-12)
        << "S^(" << k.derivative << ")(" << k.x << ")";
  // Peak factors from the derivative's roots against an independent dense measurement.
  const PolynomialPeaks peaks = polynomial_peaks(p.polynomial);
  const test::PeakFactors measured =
      test::peak_factors([&](double x, int k) { return value(p.polynomial, x, k); });
  EXPECT_NEAR(peaks.cv, measured.cv, 1e-9 * measured.cv);
  EXPECT_NEAR(peaks.ca, measured.ca, 1e-9 * measured.ca);
  EXPECT_NEAR(peaks.cj, measured.cj, 1e-9 * measured.cj);
}

// The least-jerk curve under s, v, a end conditions is the 3-4-5 quintic (its Euler–Lagrange
// equation is S⁽⁶⁾ = 0), so a degree-7 law with only those six constraints is it.
TEST(ConstrainedPolynomial, UnderDeterminedIsTheLeastJerkQuintic) {
  const ConstrainedPolynomial p = constrained_polynomial(7, rest_to_rest(2));
  EXPECT_TRUE(p.least_jerk_energy);
  expect_coefficients(p.polynomial, {0, 0, 0, 10, -15, 6, 0, 0}, 1e-9);
}

TEST(ConstrainedPolynomial, WrongCountsAreErrorsThatStateThem) {
  auto message = [](int degree, const std::vector<PolynomialConstraint>& c) {
    try {
      constrained_polynomial(degree, c);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // Over-determined: 8 constraints, degree 5.
  EXPECT_NE(
      message(5, rest_to_rest(3)).find("over-determined: 8 constraints for the 6 coefficients"),
      std::string::npos)
      << message(5, rest_to_rest(3));
  // Repeated constraint.
  std::vector<PolynomialConstraint> c = rest_to_rest(1);
  c.push_back({0.5, 0, 0.5});
  c.push_back({0.5, 0, 0.5});
  EXPECT_NE(message(5, c).find("not independent"), std::string::npos) << message(5, c);
  // s only at the ends: a quadratic x(1 − x) has no jerk, so the least jerk energy leaves it free.
  EXPECT_NE(message(7, rest_to_rest(0)).find("under-determined: 2 constraints"), std::string::npos)
      << message(7, rest_to_rest(0));
  EXPECT_THROW(constrained_polynomial(0, rest_to_rest(0)), InputError);
  EXPECT_THROW(constrained_polynomial(21, rest_to_rest(2)), InputError);
}

SegmentSpec polynomial_rise(int degree, std::vector<PolynomialConstraint> interior) {
  SegmentSpec s;
  s.name = "lift";
  s.kind = SegmentKind::Rise;
  s.law = MotionLaw::Polynomial;
  s.start = 0.3;
  s.end = 1.7;
  s.lift = 12.0;
  s.constrained_order = 2;
  s.polynomial_degree = degree;
  s.interior = std::move(interior);
  return s;
}

TEST(MotionSegment, PolynomialOfStatedDegreeFromConstraints) {
  // Degree 5 from the ends alone is the 3-4-5 rise, to 1e-12 of its size.
  SegmentSpec spec345 = polynomial_rise(5, {});
  const MotionSegment solved(spec345, 2.0);
  spec345.law = MotionLaw::Polynomial345;
  spec345.polynomial_degree = 0;
  const MotionSegment standard(spec345, 2.0);
  EXPECT_EQ(solved.polynomial_degree(), 5);
  for (int i = 0; i <= 100; ++i) {
    const double t = 0.3 + 1.4 * i / 100;
    double a[5], b[5];
    solved.derivatives(t, 4, a);
    standard.derivatives(t, 4, b);
    for (int k = 0; k <= 4; ++k) EXPECT_NEAR(a[k], b[k], 1e-12 * 12 * std::pow(1.4, -k) * 1e3);
  }
  // A return meets its interior constraint in normalised units: S(0.5) = 0.6 ⇒ s = 15 − 0.6·12.
  SegmentSpec back = polynomial_rise(0, {{0.5, 0, 0.6}});
  back.kind = SegmentKind::Return;
  const MotionSegment ret(back, 15.0);
  EXPECT_EQ(ret.polynomial_degree(), 6);
  double d[1];
  ret.derivatives(1.0, 0, d);
  EXPECT_NEAR(d[0], 15.0 - 0.6 * 12.0, 1e-12 * 15);
  // Errors name the segment and the counts.
  try {
    MotionSegment bad(polynomial_rise(5, {{0.5, 0, 0.5}}), 0.0);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("segment 'lift': over-determined: 7 constraints for the 6"),
        std::string::npos)
        << e.what();
  }
  EXPECT_THROW(MotionSegment(polynomial_rise(5, {{1.0, 0, 0.5}}), 0.0), InputError);  // x at an end
  EXPECT_THROW(MotionSegment(polynomial_rise(5, {{0.5, 5, 0.5}}), 0.0), InputError);  // k > 4
}

}  // namespace
}  // namespace polarform
