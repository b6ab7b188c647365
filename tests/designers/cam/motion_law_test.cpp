// Standard motion laws: DESIGN §4.5 coefficients measured by locating the extrema, exact boundary
// values, internal continuity of the piecewise laws, and exact derivatives against 8th-order
// finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/cam/motion_law.h"
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

double law(MotionLaw m, double x, int k) {
  double out[5];
  standard_law(m, x, 4, out);
  return out[k];
}

TEST(MotionLaw, PeakCoefficientsMatchDesignTable) {
  for (const Oracle& o : kOracles) {
    const double cv = test::dense_maximum([&](double x) { return std::abs(law(o.law, x, 1)); }, 0, 1).value;
    const double ca = test::dense_maximum([&](double x) { return std::abs(law(o.law, x, 2)); }, 0, 1).value;
    const double cj = test::dense_maximum([&](double x) { return std::abs(law(o.law, x, 3)); }, 0, 1).value;
    const std::string name(motion_law_name(o.law));
    EXPECT_NEAR(cv / o.cv, 1.0, 1e-9) << name << " Cv " << cv;
    EXPECT_NEAR(ca / o.ca, 1.0, 1e-9) << name << " Ca " << ca;
    EXPECT_NEAR(cj / o.cj, 1.0, 1e-9) << name << " Cj " << cj;
  }
}

TEST(MotionLaw, BoundaryValuesAreExact) {
  for (const Oracle& o : kOracles) {
    double a[5], b[5];
    standard_law(o.law, 0.0, 4, a);
    standard_law(o.law, 1.0, 4, b);
    const std::string name(motion_law_name(o.law));
    EXPECT_EQ(a[0], 0.0) << name;
    EXPECT_EQ(b[0], 1.0) << name;
    EXPECT_EQ(a[1], 0.0) << name;
    EXPECT_EQ(b[1], 0.0) << name;
    if (o.law == MotionLaw::SimpleHarmonic) {  // the harmonic law starts and ends accelerating
      EXPECT_EQ(a[2], pi * pi / 2);
      EXPECT_EQ(b[2], -pi * pi / 2);
    } else {
      EXPECT_EQ(a[2], 0.0) << name;
      EXPECT_EQ(b[2], 0.0) << name;
    }
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

// s', s'', s''', s'''' against the 8th-order difference of the derivative below, away from joints.
TEST(MotionLaw, DerivativesAgreeWithFiniteDifferences) {
  const double h = 1e-3;
  for (const Oracle& o : kOracles) {
    for (int i = 1; i < 200; ++i) {
      const double x = i / 200.0;
      if (std::abs(std::fmod(x, 0.125)) < 6 * h || 0.125 - std::fmod(x, 0.125) < 6 * h) continue;
      for (int k = 1; k <= 4; ++k) {
        const double fd = test::central_difference([&](double t) { return law(o.law, t, k - 1); }, x, h);
        EXPECT_NEAR(law(o.law, x, k), fd, 1e-7 * std::max(1.0, std::abs(fd)))
            << motion_law_name(o.law) << " derivative " << k << " at x = " << x;
      }
    }
  }
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
}

TEST(MotionLaw, NamesRoundTripAndUnknownNamesAreRejected) {
  for (MotionLaw m : {MotionLaw::SimpleHarmonic, MotionLaw::Cycloidal, MotionLaw::ModifiedTrapezoid,
                      MotionLaw::ModifiedSine, MotionLaw::Polynomial345, MotionLaw::Polynomial4567,
                      MotionLaw::Polynomial, MotionLaw::BSpline})
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
