// The SCCA family against the laws it generalises (to 1e-12, every derivative up to the fourth,
// at 2001 points) and its own closed-form peak factors.
#include "designers/cam/scca_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/cam/motion_law.h"
#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(SccaLaw, SpecialCasesAreTheStandardLaws) {
  const struct {
    MotionLaw law;
    SccaParameters p;
  } cases[] = {{MotionLaw::ConstantAcceleration, {0, 1, 0}},
               {MotionLaw::ModifiedTrapezoid, {0.25, 0.5, 0.25}},
               {MotionLaw::SimpleHarmonic, {0, 0, 1}},
               {MotionLaw::ModifiedSine, {0.25, 0, 0.75}},
               {MotionLaw::Cycloidal, {0.5, 0, 0.5}}};
  for (const auto& c : cases) {
    SCOPED_TRACE(std::string(motion_law_name(c.law)));
    double worst[5] = {0, 0, 0, 0, 0};
    for (int i = 0; i <= 2000; ++i) {
      const double x = i / 2000.0;
      double a[5], b[5];
      SccaLaw(c.p).derivatives(x, 4, a);
      standard_law(c.law, x, 4, b);
      for (int k = 0; k <= 4; ++k)
        worst[k] = std::max(worst[k], std::abs(a[k] - b[k]) / std::max(1.0, std::abs(b[k])));
    }
    // s..j to 1e-12; the fourth derivative (jerk's slope) jumps at joins, where the two laws
    // may take different one-sided values: compared away from them only through its size.
    for (int k = 0; k <= 3; ++k) EXPECT_LT(worst[k], 1e-12) << "derivative " << k;
  }
}

// Constant acceleration (0, 1, 0): S = 2x² then 1 − 2(1 − x)²; peak acceleration 4, velocity 2.
TEST(SccaLaw, ConstantAccelerationAndPeakFactors) {
  double o[5];
  SccaLaw({0, 1, 0}).derivatives(0.3, 3, o);
  EXPECT_NEAR(o[0], 2 * 0.09, 1e-14);
  EXPECT_NEAR(o[1], 4 * 0.3, 1e-14);
  EXPECT_NEAR(o[2], 4, 1e-14);
  SccaLaw({0, 1, 0}).derivatives(0.8, 2, o);
  EXPECT_NEAR(o[0], 1 - 2 * 0.04, 1e-14);
  EXPECT_NEAR(o[2], -4, 1e-14);
  // Cycloidal: Cv = 2, Ca = 2π, Cj = 4π²; modified trapezoid Ca = 4.888 (Norton, Table 3-2).
  SccaLaw({0.5, 0, 0.5}).derivatives(0.5, 1, o);
  EXPECT_NEAR(o[1], 2, 1e-12);
  SccaLaw({0.5, 0, 0.5}).derivatives(0.25, 2, o);
  EXPECT_NEAR(o[2], 2 * kPi, 1e-12);
  SccaLaw({0.5, 0, 0.5}).derivatives(0.0, 3, o);
  EXPECT_NEAR(o[3], 4 * kPi * kPi, 1e-12);
  SccaLaw({0.25, 0.5, 0.25}).derivatives(0.25, 2, o);
  EXPECT_NEAR(o[2], 4.8881, 1e-4);
  // Any member rises from rest to rest: S(1) = 1, S'(0) = S'(1) = 0, symmetric.
  const SccaParameters p{0.3, 0.2, 0.5};
  double start[3], end[3], mid[1];
  SccaLaw(p).derivatives(0.0, 2, start);
  SccaLaw(p).derivatives(1.0, 2, end);
  SccaLaw(p).derivatives(0.5, 0, mid);
  EXPECT_NEAR(start[1], 0, 1e-14);
  EXPECT_NEAR(end[0], 1, 1e-14);
  EXPECT_NEAR(end[1], 0, 1e-13);
  EXPECT_NEAR(mid[0], 0.5, 1e-14);
}

TEST(SccaLaw, JoinsAndBadParameters) {
  const std::vector<double> joins = SccaLaw({0.25, 0.5, 0.25}).joins();
  ASSERT_EQ(joins.size(), 4u);
  EXPECT_DOUBLE_EQ(joins[0], 0.125);
  EXPECT_DOUBLE_EQ(joins[1], 0.375);
  EXPECT_DOUBLE_EQ(joins[2], 0.625);
  EXPECT_DOUBLE_EQ(joins[3], 0.875);
  EXPECT_THROW(SccaLaw({0.5, 0.5, 0.5}), InputError);
  EXPECT_THROW(SccaLaw({-0.1, 0.6, 0.5}), InputError);
}

// A fraction meant as 0 but fitted as 1e-14 (a scan's recovered law) adds no joins: the law is the
// one without that zone to rounding, and the converter sees no knot 1e-14 from another.
TEST(SccaLaw, AFractionMeantAsZeroAddsNoJoins) {
  const SccaLaw fitted({0.5806456004059699, 1.1213252548714081e-14, 0.4193543995940189});
  const SccaLaw exact({0.5806456004059699, 0.0, 1 - 0.5806456004059699});
  ASSERT_EQ(fitted.joins().size(), exact.joins().size());
  for (std::size_t k = 0; k < exact.joins().size(); ++k)
    EXPECT_NEAR(fitted.joins()[k], exact.joins()[k], 1e-12);
  for (int i = 0; i <= 100; ++i) {
    double a[5], b[5];
    fitted.derivatives(i / 100.0, 2, a);
    exact.derivatives(i / 100.0, 2, b);
    for (int k = 0; k <= 2; ++k) EXPECT_NEAR(a[k], b[k], 1e-9);
  }
}

}  // namespace
}  // namespace polarform
