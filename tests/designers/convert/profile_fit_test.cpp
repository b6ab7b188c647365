// The degree-limited fit's parts: R's table agrees with R between and at its nodes (at bucket
// starts too, where a lookup's rounding may land a node late), Lawson's steps lower the largest
// sample error of the plain least-squares fit, and a fit handed a target it cannot meet stops its
// steps where ProfileFitOptions says (its result is then the fewer steps' own).
#include "designers/convert/profile_fit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

// A closed cam-like profile, 40 + 6 sin θ + 2 cos 3θ mm, with a breakpoint where nothing jumps.
PolarFunction wavy() {
  PolarFunction R;
  R.start = 0, R.end = 2 * kPi;
  R.breakpoints = {1.0};
  R.derivatives = [](double t, int d, double* out) {
    const double v[4] = {
        40 + 6 * std::sin(t) + 2 * std::cos(3 * t), 6 * std::cos(t) - 6 * std::sin(3 * t),
        -6 * std::sin(t) - 18 * std::cos(3 * t), -6 * std::cos(t) + 54 * std::sin(3 * t)};
    for (int k = 0; k <= d; ++k) out[k] = v[k];
  };
  return R;
}

std::vector<double> uniform(double a, double b, int spans) {
  std::vector<double> out;
  for (int i = 0; i <= spans; ++i) out.push_back(i == spans ? b : a + (b - a) * i / spans);
  return out;
}

double largest(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

TEST(ProfileTable, AgreesWithRBetweenAndAtItsNodes) {
  const PolarFunction R = wavy();
  for (int intervals : {64, 512}) {
    const ProfileTable table(R, intervals);
    const double h = 2 * kPi / intervals;
    // The quintic Hermite interpolant's error is about h^6 R^(6) / 46080 (R^(6) <= 1464 here).
    const double bound = 2 * std::pow(h, 6) * 1464 / 46080 + 1e-12;
    double worst = 0.0, worst_slope = 0.0;
    for (int k = 0; k <= 4 * intervals; ++k) {
      // Quarter steps, each side of every node (2π/intervals·k rounds either way) and the seam.
      for (double t :
           {k * h / 4, std::nextafter(k * h / 4, -1.0), std::nextafter(k * h / 4, 10.0)}) {
        const double tt = std::clamp(t, R.start, R.end);
        double d[2], exact[2];
        table.derivatives(tt, d);
        R.derivatives(tt, 1, exact);
        worst = std::max(worst, std::abs(d[0] - exact[0]));
        worst_slope = std::max(worst_slope, std::abs(d[1] - exact[1]));
      }
    }
    EXPECT_LE(worst, bound) << intervals;
    EXPECT_LE(worst_slope, 20 * bound / h) << intervals;
  }
  // Closed: ψ wraps by the period.
  const ProfileTable table(R, 512);
  EXPECT_NEAR(table(0.3 + 2 * kPi), R(0.3), 1e-9);
  EXPECT_NEAR(table(0.3 - 2 * kPi), R(0.3), 1e-9);
}

TEST(ProfileFit, LawsonsStepsLowerTheLargestSampleError) {
  const PolarFunction R = wavy();
  const ProfileTable table(R, 512);
  const SplineSpace space(4, Ends::periodic, uniform(R.start, R.end, 8));
  const FittedProfile plain = fit_profile(space, table, {10, 1e-5, 0});
  const FittedProfile minimax = fit_profile(space, table, {10, 1e-5, 8});
  ASSERT_EQ(plain.sample_errors.size(), 8u);
  // Measured densely on the table, not by the fits' own samples.
  const double e_plain = largest(span_errors(space, plain.coefs, table, 40));
  const double e_minimax = largest(span_errors(space, minimax.coefs, table, 40));
  EXPECT_GT(e_plain, 1e-4);  // a fit that has something to gain
  EXPECT_LT(e_minimax, 0.8 * e_plain);
  // The samples' largest error is the densest's, nearly.
  EXPECT_LE(largest(minimax.sample_errors), e_minimax);
  EXPECT_GE(largest(minimax.sample_errors), 0.8 * e_minimax);
}

TEST(ProfileFit, AFitThatCannotMeetItsTargetStopsItsStepsEarly) {
  const PolarFunction R = wavy();
  const ProfileTable table(R, 512);
  const SplineSpace space(4, Ends::periodic, uniform(R.start, R.end, 8));
  ProfileFitOptions full{10, 1e-5, 8};
  const FittedProfile all = fit_profile(space, table, full);
  const double reached = largest(all.sample_errors);
  // A target 100 times below what 8 steps reach: after step 1 the error exceeds target·(1 + 3/1),
  // so the fit is the one of a single step.
  ProfileFitOptions hopeless = full;
  hopeless.target = reached / 100;
  ProfileFitOptions one_step = full;
  one_step.lawson_steps = 1;
  const FittedProfile given_up = fit_profile(space, table, hopeless);
  EXPECT_EQ(given_up.coefs, fit_profile(space, table, one_step).coefs);
  EXPECT_GT(largest(given_up.sample_errors), reached);
  // A target the steps come down to steadily (half the plain fit's error; the steps here take
  // the error from 2.2 mm to 1.0, 0.14, 0.060, ... 0.044 mm): every step is taken, as without one.
  ProfileFitOptions plain = full, reachable = full;
  plain.lawson_steps = 0;
  reachable.target = largest(fit_profile(space, table, plain).sample_errors) / 2;
  EXPECT_EQ(fit_profile(space, table, reachable).coefs, all.coefs);
}

}  // namespace
}  // namespace polarform
