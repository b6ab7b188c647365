// refined_maximum: the maximum of a function between samples, located by Brent's search.
#include "designers/convert/refined_maximum.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace polarform {
namespace {

TEST(RefinedMaximum, FindsAPeakBetweenSamplesToRoundOff) {
  int calls = 0;
  const auto f = [&](double t) {
    ++calls;
    return 2.0 - (t - 0.3137) * (t - 0.3137);
  };
  const Maximum m = refined_maximum(f, {0.0, 0.5, 1.0}, 4, 3);
  EXPECT_NEAR(m.at, 0.3137, 1e-7);
  EXPECT_NEAR(m.value, 2.0, 1e-14);
  // A parabola: Brent's first parabolic step lands on it (9 samples, a few steps).
  EXPECT_LE(calls, 9 + 3 * 4);
}

TEST(RefinedMaximum, TakesTheLargestOfManyBumps) {
  // |sin(7t)|·(1 + t/10) on [0, 1]: bumps at t = (k + 1/2)π/7 shifted slightly by the ramp; the
  // largest at k = 1 (t ≈ 0.6732), value from a dense scan.
  const auto f = [](double t) { return std::abs(std::sin(7 * t)) * (1 + t / 10); };
  double best = 0.0, at = 0.0;
  for (int k = 0; k <= 1000000; ++k) {
    const double t = k / 1e6;
    if (f(t) > best) best = f(t), at = t;
  }
  int calls = 0;
  const Maximum m = refined_maximum(
      [&](double t) {
        ++calls;
        return f(t);
      },
      {0.0, 0.25, 0.5, 0.75, 1.0}, 3, 10);
  EXPECT_NEAR(m.value, best, 1e-12);
  EXPECT_NEAR(m.at, at, 2e-6);
  EXPECT_LT(calls, 13 + 3 * 12);  // 13 samples, 3 peaks refined in a dozen steps each at most
}

TEST(RefinedMaximum, RefinesAPeakAtTheGridsEnd) {
  const Maximum m = refined_maximum([](double t) { return t; }, {0.0, 1.0}, 8, 2);
  EXPECT_EQ(m.at, 1.0);
  EXPECT_EQ(m.value, 1.0);
}

}  // namespace
}  // namespace polarform
