// Standard motion laws: DESIGN §4.5 coefficients measured by locating the extrema, exact boundary
// values, internal continuity of the piecewise laws, and exact derivatives against 8th-order
// finite differences.
#include "designers/cam/motion_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <span>

#include "src/error.h"
#include "tests/designers/cam/cam_test_support.h"

namespace polarform {
namespace {

constexpr double pi = std::numbers::pi;

struct Oracle {
  MotionLaw law;
  double cv, ca, cj;
};

// DESIGN §4.5 (harmonic: the jerk inside the segment, π³/2).
const Oracle kOracles[] = {
    {MotionLaw::SimpleHarmonic, pi / 2, pi * pi / 2, pi * pi * pi / 2},
    {MotionLaw::Cycloidal, 2, 2 * pi, 4 * pi * pi},
    {MotionLaw::ModifiedTrapezoid, 2, 8 * pi / (pi + 2), 32 * pi * pi / (pi + 2)},
    {MotionLaw::ModifiedSine, 4 * pi / (4 + pi), 4 * pi * pi / (4 + pi), 16 * pi * pi * pi / (4 + pi)},
    {MotionLaw::Polynomial345, 15.0 / 8, 10 / std::sqrt(3.0), 60},
    {MotionLaw::Polynomial4567, 35.0 / 16, 84 * std::sqrt(5.0) / 25, 52.5},
};

// The laws added for issue 15, peak factors as closed forms. Constant acceleration: Norton,
// Handbook, table of peak factors (Cv 2, Ca 4, Cj infinite at 0, ½, 1 and 0 between). Cubic
// 3x² − 2x³ and double harmonic ½[(1 − cos πx) − ¼(1 − cos 2πx)] (Rothbart, Cams, 1956): derived by
// hand, the book lists the curves but no factors. Cubic: S' = 6x(1 − x) peaks at ½, S'' = 6 − 12x
// at the ends, S‴ = −12. Double harmonic: S' peaks at x = ⅔ (cos πx = cos 2πx), |S''| at x = 1
// (−π²; the interior extremum 9π²/16 is smaller), |S‴| where cos πx = (1 − √129)/16.
const Oracle kAddedOracles[] = {
    {MotionLaw::ConstantAcceleration, 2, 4, 0},
    {MotionLaw::Cubic, 1.5, 6, 12},
    {MotionLaw::DoubleHarmonic, 3 * std::sqrt(3.0) * pi / 8, pi* pi,
     pi* pi* pi / 2 * (3 + std::sqrt(129.0)) / 4 * std::sqrt(126 + 2 * std::sqrt(129.0)) / 16},
};

double law(MotionLaw m, double x, int k) {
  double out[5];
  standard_law(m, x, 4, out);
  return out[k];
}

// Measured peaks against the oracle's, to 1e-9 relative (absolute for a zero peak).
void expect_peaks(const Oracle& o) {
  const test::PeakFactors p = test::peak_factors([&](double x, int k) { return law(o.law, x, k); });
  const std::string name(motion_law_name(o.law));
  EXPECT_NEAR(p.cv, o.cv, 1e-9 * std::max(1.0, o.cv)) << name << " Cv " << p.cv;
  EXPECT_NEAR(p.ca, o.ca, 1e-9 * std::max(1.0, o.ca)) << name << " Ca " << p.ca;
  EXPECT_NEAR(p.cj, o.cj, 1e-9 * std::max(1.0, o.cj)) << name << " Cj " << p.cj;
}

// Derivatives 1..4 against the 8th-order difference of the derivative below, at x = i/200 except
// where skip(x, 6h) says a join is near.
template <class Skip>
void expect_derivatives_match_differences(MotionLaw m, Skip skip) {
  const double h = 1e-3;
  for (int i = 1; i < 200; ++i) {
    const double x = i / 200.0;
    if (skip(x, 6 * h)) continue;
    for (int k = 1; k <= 4; ++k) {
      const double fd = test::central_difference([&](double t) { return law(m, t, k - 1); }, x, h);
      EXPECT_NEAR(law(m, x, k), fd, 1e-7 * std::max(1.0, std::abs(fd)))
          << motion_law_name(m) << " derivative " << k << " at x = " << x;
    }
  }
}

TEST(MotionLaw, PeakCoefficientsMatchDesignTable) {
  for (const Oracle& o : kOracles) expect_peaks(o);
}

// The accelerations at x = 0 and 1: zero except the harmonic law (±π²/2), constant acceleration
// (±4), the cubic (±6) and the double harmonic (0 and −π²: it ends decelerating).
std::pair<double, double> end_accelerations(MotionLaw m) {
  switch (m) {
    case MotionLaw::SimpleHarmonic:
      return {pi * pi / 2, -pi * pi / 2};
    case MotionLaw::ConstantAcceleration:
      return {4, -4};
    case MotionLaw::Cubic:
      return {6, -6};
    case MotionLaw::DoubleHarmonic:
      return {0, -pi * pi};
    default:
      return {0, 0};
  }
}

TEST(MotionLaw, BoundaryValuesAreExact) {
  for (const std::span<const Oracle> oracles :
       {std::span<const Oracle>(kOracles), std::span<const Oracle>(kAddedOracles)})
    for (const Oracle& o : oracles) {
      double a[5], b[5];
      standard_law(o.law, 0.0, 4, a);
      standard_law(o.law, 1.0, 4, b);
      const std::string name(motion_law_name(o.law));
      EXPECT_EQ(a[0], 0.0) << name;
      EXPECT_NEAR(b[0], 1.0, 1e-15) << name;
      EXPECT_NEAR(a[1], 0.0, 1e-15) << name;
      EXPECT_NEAR(b[1], 0.0, 1e-15) << name;
      EXPECT_NEAR(a[2], end_accelerations(o.law).first, 1e-14) << name;
      EXPECT_NEAR(b[2], end_accelerations(o.law).second, 1e-14) << name;
    }
  double a[5], b[5];
  standard_law(MotionLaw::Polynomial4567, 0.0, 3, a);
  standard_law(MotionLaw::Polynomial4567, 1.0, 3, b);
  EXPECT_EQ(a[3], 0.0);
  EXPECT_EQ(b[3], 0.0);
}

// Every law is antisymmetric about (1/2, 1/2), which fixes the peak constants of the piecewise laws.
TEST(MotionLaw, HalfwayAndPieceJoinsAreContinuous) {
  for (const Oracle& o : kOracles) EXPECT_NEAR(law(o.law, 0.5, 0), 0.5, 1e-15) << motion_law_name(o.law);
  for (MotionLaw m : {MotionLaw::ModifiedTrapezoid, MotionLaw::ModifiedSine})
    for (double joint : {0.125, 0.375, 0.625, 0.875})
      for (int k = 0; k <= 3; ++k)
        EXPECT_NEAR(law(m, joint - 1e-13, k), law(m, joint + 1e-13, k), 1e-9)
            << motion_law_name(m) << " derivative " << k << " at " << joint;
}

// Away from the joins (multiples of 1/8).
TEST(MotionLaw, DerivativesAgreeWithFiniteDifferences) {
  for (const Oracle& o : kOracles)
    expect_derivatives_match_differences(o.law, [](double x, double near) {
      return std::abs(std::fmod(x, 0.125)) < near || 0.125 - std::fmod(x, 0.125) < near;
    });
}

TEST(MotionLaw, AddedLawsPeakCoefficientsMatchClosedForms) {
  for (const Oracle& o : kAddedOracles) expect_peaks(o);
  EXPECT_NEAR(kAddedOracles[2].cj, 42.41372003137923,
              1e-12);  // the closed form, evaluated by sympy
  EXPECT_EQ(law_joins(MotionLaw::ConstantAcceleration), std::vector<double>{0.5});
}

TEST(MotionLaw, OnlyTheDoubleHarmonicIsNotAntisymmetric) {
  EXPECT_TRUE(is_antisymmetric_law(MotionLaw::Cubic));
  EXPECT_FALSE(is_antisymmetric_law(MotionLaw::DoubleHarmonic));
  EXPECT_NEAR(law(MotionLaw::DoubleHarmonic, 0.5, 0), 0.25, 1e-15);  // ½[1 − ¼·2]: not halfway
}

TEST(MotionLaw, AddedLawsDerivativesAgreeWithFiniteDifferences) {
  for (const Oracle& o : kAddedOracles)  // away from constant acceleration's join at 1/2
    expect_derivatives_match_differences(
        o.law, [](double x, double near) { return std::abs(x - 0.5) < near; });
}

TEST(MotionLaw, PolynomialLawsHaveTheirPowerForm) {
  const Polynomial p = *standard_law_polynomial(MotionLaw::Polynomial345);
  EXPECT_EQ(p.coefficients(), (std::vector<double>{0, 0, 0, 10, -15, 6}));
  for (double x = 0; x <= 1; x += 0.01) {
    double d[4];
    p.derivatives(x, 3, d);
    for (int k = 0; k <= 3; ++k) EXPECT_NEAR(d[k], law(MotionLaw::Polynomial345, x, k), 1e-12);
  }
  EXPECT_FALSE(standard_law_polynomial(MotionLaw::Cycloidal));
  EXPECT_EQ(standard_law_polynomial(MotionLaw::Cubic)->coefficients(),
            (std::vector<double>{0, 0, 3, -2}));
}

TEST(MotionLaw, NamesRoundTripAndUnknownNamesAreRejected) {
  for (MotionLaw m :
       {MotionLaw::SimpleHarmonic, MotionLaw::Cycloidal, MotionLaw::ModifiedTrapezoid,
        MotionLaw::ModifiedSine, MotionLaw::Polynomial345, MotionLaw::Polynomial4567,
        MotionLaw::Polynomial, MotionLaw::BSpline, MotionLaw::ConstantAcceleration,
        MotionLaw::Cubic, MotionLaw::DoubleHarmonic, MotionLaw::ConstantVelocity, MotionLaw::Table})
    EXPECT_EQ(parse_motion_law(motion_law_name(m)), m);
  try {
    parse_motion_law("parabolic");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown motion law 'parabolic'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cycloidal"), std::string::npos) << e.what();
  }
  double out[5];
  EXPECT_THROW(standard_law(MotionLaw::BSpline, 0.5, 2, out), InputError);
}

}  // namespace
}  // namespace polarform
