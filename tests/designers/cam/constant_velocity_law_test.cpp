// Constant velocity with cycloidal blends: peak factors against the closed forms derived by hand
// (Cv = 1/(1 − f), Ca = π/(2f(1 − f)), Cj = π²/(2f²(1 − f)) for blend fraction f), the blend ½
// being the cycloidal law to 1e-12, f = 0 the pure S = x, continuity of s, v, a at the blends'
// ends, and exact derivatives against finite differences.
#include "designers/cam/constant_velocity_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/cam/motion_law.h"
#include "src/error.h"
#include "tests/designers/cam/cam_test_support.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

double law(const ConstantVelocityLaw& l, double x, int k) {
  double out[5];
  l.derivatives(x, 4, out);
  return out[k];
}

TEST(ConstantVelocityLaw, PeakFactorsMatchClosedForms) {
  for (double f : {0.05, 0.1, 0.2, 0.25, 0.4}) {
    SCOPED_TRACE(f);
    const ConstantVelocityLaw l(f);
    const test::PeakFactors p = test::peak_factors([&](double x, int k) { return law(l, x, k); });
    EXPECT_NEAR(p.cv, 1 / (1 - f), 1e-9);
    EXPECT_NEAR(p.ca, kPi / (2 * f * (1 - f)), 1e-9 * p.ca);
    EXPECT_NEAR(p.cj, kPi * kPi / (2 * f * f * (1 - f)), 1e-9 * p.cj);
    EXPECT_EQ(l.joins(), (std::vector<double>{f, 1 - f}));
  }
  // f = 0.2: Cv 1.25, Ca 9.8175, Cj 154.2126 (the closed forms evaluated).
  EXPECT_NEAR(ConstantVelocityLaw(0.2).peak_acceleration(), 9.817477042468104, 1e-12);
}

TEST(ConstantVelocityLaw, HalfBlendIsTheCycloidalLaw) {
  const ConstantVelocityLaw l(0.5);
  EXPECT_TRUE(l.joins().empty());
  for (int i = 0; i <= 2000; ++i) {
    const double x = i / 2000.0;
    double a[5], b[5];
    l.derivatives(x, 4, a);
    standard_law(MotionLaw::Cycloidal, x, 4, b);
    for (int k = 0; k <= 3; ++k)
      EXPECT_NEAR(a[k], b[k], 1e-12 * std::max(1.0, std::abs(b[k]))) << x << " " << k;
  }
}

TEST(ConstantVelocityLaw, EndsJoinsAndPureConstantVelocity) {
  const ConstantVelocityLaw l(0.2);
  for (double x : {0.0, 1.0}) {
    EXPECT_NEAR(law(l, x, 0), x, 1e-15);
    EXPECT_NEAR(law(l, x, 1), 0, 1e-15);
    EXPECT_NEAR(law(l, x, 2), 0, 1e-12);
  }
  EXPECT_NEAR(law(l, 0.5, 0), 0.5, 1e-15);
  for (double join : {0.2, 0.8})
    for (int k = 0; k <= 2; ++k)
      EXPECT_NEAR(law(l, join - 1e-12, k), law(l, join + 1e-12, k), 1e-9) << join << " " << k;
  EXPECT_NEAR(law(l, 0.3, 1), 1.25, 1e-15);
  EXPECT_NEAR(law(l, 0.3, 0), 1.25 * (0.3 - 0.1), 1e-15);  // S = V(x − f/2)
  const ConstantVelocityLaw pure(0.0);
  EXPECT_TRUE(pure.joins().empty());
  EXPECT_EQ(pure.peak_acceleration(), HUGE_VAL);
  for (double x : {0.0, 0.3, 0.7, 1.0}) {
    EXPECT_NEAR(law(pure, x, 0), x, 1e-15);
    EXPECT_EQ(law(pure, x, 1), 1.0);
    EXPECT_EQ(law(pure, x, 2), 0.0);
  }
  EXPECT_THROW(ConstantVelocityLaw(0.6), InputError);
  EXPECT_THROW(ConstantVelocityLaw(-0.1), InputError);
  EXPECT_THROW(ConstantVelocityLaw(std::nan("")), InputError);
}

TEST(ConstantVelocityLaw, DerivativesAgreeWithFiniteDifferences) {
  const ConstantVelocityLaw l(0.3);
  const double h = 1e-3;
  for (int i = 1; i < 200; ++i) {
    const double x = i / 200.0;
    if (std::abs(x - 0.3) < 6 * h || std::abs(x - 0.7) < 6 * h) continue;
    for (int k = 1; k <= 4; ++k) {
      const double fd = test::central_difference([&](double t) { return law(l, t, k - 1); }, x, h);
      EXPECT_NEAR(law(l, x, k), fd, 1e-7 * std::max(1.0, std::abs(fd))) << k << " at " << x;
    }
  }
}

}  // namespace
}  // namespace polarform
