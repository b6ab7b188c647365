// Bernstein root isolation: power-to-Bernstein conversion against direct evaluation, and isolating
// intervals for polynomials with known roots (close pairs, roots at the ends, a double root).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "src/nurbs/bernstein_roots.h"

namespace polarform {
namespace {

// Power coefficients of prod (t − r_i) times `lead`.
std::vector<double> from_roots(const std::vector<double>& roots, double lead = 1.0) {
  std::vector<double> c = {lead};
  for (double r : roots) {
    std::vector<double> next(c.size() + 1, 0.0);
    for (std::size_t k = 0; k < c.size(); ++k) {
      next[k + 1] += c[k];
      next[k] -= r * c[k];
    }
    c = next;
  }
  return c;
}

// de Casteljau evaluation of a Bernstein polynomial on [0, 1].
double bernstein_value(std::vector<double> b, double t) {
  for (std::size_t r = 1; r < b.size(); ++r)
    for (std::size_t i = 0; i + r < b.size(); ++i) b[i] = (1 - t) * b[i] + t * b[i + 1];
  return b[0];
}

double power_value(const std::vector<double>& c, double t) {
  double v = 0;
  for (std::size_t k = c.size(); k-- > 0;) v = v * t + c[k];
  return v;
}

TEST(BernsteinRoots, ConversionMatchesPowerForm) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> coef(-3, 3);
  for (int degree = 0; degree <= 14; ++degree) {
    std::vector<double> c(degree + 1);
    for (double& x : c) x = coef(rng);
    const std::vector<double> b = power_to_bernstein(c);
    ASSERT_EQ(b.size(), c.size());
    EXPECT_NEAR(b.front(), c.front(), 1e-15);
    for (double t = 0; t <= 1.0; t += 1.0 / 64)
      EXPECT_NEAR(bernstein_value(b, t), power_value(c, t), 1e-12) << degree << " " << t;
  }
}

// Every simple root lies in exactly one interval, each interval holds exactly one root.
void expect_isolated(const std::vector<double>& roots, const std::vector<double>& power) {
  const auto intervals = isolate_roots(power_to_bernstein(power));
  ASSERT_EQ(intervals.size(), roots.size());
  for (std::size_t i = 0; i < roots.size(); ++i) {
    EXPECT_LE(intervals[i].first, roots[i]);
    EXPECT_GE(intervals[i].second, roots[i]);
    if (i > 0) {
      EXPECT_LE(intervals[i - 1].second, intervals[i].first);
    }
  }
}

TEST(BernsteinRoots, IsolatesKnownRoots) {
  expect_isolated({0.3, 0.5, 0.8}, from_roots({0.3, 0.5, 0.8}));
  expect_isolated({0.25, 0.25 + 1e-6, 0.9}, from_roots({0.25, 0.25 + 1e-6, 0.9}, -2.0));
  expect_isolated({0.1, 0.7}, from_roots({-0.4, 0.1, 0.7, 1.6}));  // roots outside [0, 1] ignored
  expect_isolated({0.05, 0.15, 0.35, 0.55, 0.6, 0.95}, from_roots({0.05, 0.15, 0.35, 0.55, 0.6, 0.95}));
  // No roots: a positive quadratic, a constant, the zero polynomial.
  EXPECT_TRUE(isolate_roots(power_to_bernstein({1.0, -1.0, 1.0})).empty());
  EXPECT_TRUE(isolate_roots(power_to_bernstein({2.0})).empty());
  EXPECT_TRUE(isolate_roots(power_to_bernstein({0.0, 0.0, 0.0})).empty());
}

TEST(BernsteinRoots, DoubleRootStaysLocal) {
  // (t − 0.4)² (t − 0.8): near the double root the polynomial is below rounding within ~1e-8, so
  // only narrow intervals around 0.4 may appear there; the simple root is isolated.
  const auto intervals = isolate_roots(power_to_bernstein(from_roots({0.4, 0.4, 0.8})), 1e-9);
  ASSERT_FALSE(intervals.empty());
  EXPECT_LE(intervals.back().first, 0.8);
  EXPECT_GE(intervals.back().second, 0.8);
  EXPECT_GE(intervals.back().first, 0.5);
  for (std::size_t i = 0; i + 1 < intervals.size(); ++i) {
    EXPECT_GT(intervals[i].first, 0.4 - 1e-6);
    EXPECT_LT(intervals[i].second, 0.4 + 1e-6);
  }
}

}  // namespace
}  // namespace polarform
