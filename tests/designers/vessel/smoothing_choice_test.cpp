// The smoothing weight chosen from the targets (smoothing_choice.h): the shape-preserving rule on
// targets that a small fixed weight meets by ringing, the tolerance rule's largest weight, and a
// smooth profile's targets, which the first weight tried already meets.
#include "designers/vessel/smoothing_choice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/vessel/polar_curvature.h"
#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

SynthesisProblem custom_problem() {
  SynthesisProblem p;
  p.length_unit = 500;
  p.targets = {{10 * kDeg, 0.0032, 1},     {25 * kDeg, 0.0028, 1},    {45 * kDeg, 1 / 450.0, 1},
               {70 * kDeg, 1 / 550.0, 2},  {90 * kDeg, 1 / 600.0, 2}, {110 * kDeg, 1 / 550.0, 2},
               {135 * kDeg, 1 / 450.0, 1}, {155 * kDeg, 0.0028, 1},   {170 * kDeg, 0.0032, 1}};
  p.end_a = p.end_b = EndCondition::thesis_default(500);
  return p;
}

// Local extrema of κ on 721 angles whose prominence exceeds h (1/mm).
int kappa_extrema(const BSplineFunction& R, double h) {
  std::vector<double> k;
  for (int i = 0; i <= 720; ++i) {
    const Eigen::VectorXd d = R.derivatives(kPi * i / 720, 2);
    k.push_back(polar_curvature(d(0), d(1), d(2)));
  }
  int count = 0, direction = 0;
  double extreme = k.front();
  for (double v : k) {
    if (direction >= 0 && v < extreme - h)
      count += direction > 0, direction = -1, extreme = v;
    else if (direction <= 0 && v > extreme + h)
      count += direction < 0, direction = 1, extreme = v;
    else if ((direction > 0 && v > extreme) || (direction < 0 && v < extreme))
      extreme = v;
  }
  return count;
}

// The targets rise from the junction's 1/500 to 0.0032, fall to 1/600 at the apex and rise again:
// 3 turning points. λ = 1e-4 meets them to 2e-6 by a curvature with more (a dip to 0.00075
// between 45° and 70°); the chosen λ has 3, no κ < 0, and 0.93 of it rings again.
TEST(SmoothingChoice, ShapePreservingRemovesTheRinging) {
  SynthesisProblem p = custom_problem();
  p.settings.smoothing = 1e-4;
  const SynthesisResult fixed = synthesize_profile(p);
  const double h = 0.01 * (0.0032 - 1 / 600.0);
  EXPECT_GE(kappa_extrema(fixed.profile, h), 5);
  p.settings.smoothing_rule = SmoothingRule::shape_preserving;
  SmoothingChoice choice;
  const SynthesisResult chosen = synthesize_with_chosen_smoothing(p, choice);
  EXPECT_TRUE(choice.met);
  EXPECT_EQ(choice.target_turning_points, 3);
  EXPECT_EQ(choice.turning_points, 3);
  EXPECT_EQ(kappa_extrema(chosen.profile, h), 3);
  for (int i = 0; i <= 720; ++i) {
    const Eigen::VectorXd d = chosen.profile.derivatives(kPi * i / 720, 2);
    EXPECT_GT(polar_curvature(d(0), d(1), d(2)), 0.0);
  }
  RecordProperty("lambda", std::to_string(chosen.smoothing));
  p.settings.smoothing = 0.93 * chosen.smoothing;
  p.settings.smoothing_rule = SmoothingRule::fixed;
  EXPECT_GT(kappa_extrema(synthesize_profile(p).profile, h), 3);
}

// The largest λ that meets every target within 2e-4 1/mm: met, and 1.1 λ misses.
TEST(SmoothingChoice, ToleranceTakesTheLargestWeightThatMeetsIt) {
  SynthesisProblem p = custom_problem();
  p.settings.smoothing_rule = SmoothingRule::tolerance;
  p.settings.kappa_tolerance = 2e-4;
  SmoothingChoice choice;
  const SynthesisResult r = synthesize_with_chosen_smoothing(p, choice);
  EXPECT_TRUE(choice.met);
  for (const TargetResidual& t : r.targets) EXPECT_LE(std::abs(t.residual()), 2e-4);
  EXPECT_GT(choice.max_residual, 0.5 * 2e-4);
  p.settings.smoothing_rule = SmoothingRule::fixed;
  p.settings.smoothing = 1.1 * r.smoothing;
  double worst = 0.0;
  for (const TargetResidual& t : synthesize_profile(p).targets)
    worst = std::max(worst, std::abs(t.residual()));
  EXPECT_GT(worst, 2e-4);
  p.settings.smoothing_rule = SmoothingRule::tolerance;
  p.settings.kappa_tolerance = 0.0;
  EXPECT_THROW(synthesize_with_chosen_smoothing(p, choice), InputError);
}

// A circle's targets: the first λ tried (1e-10) keeps the circle's shape, one trial.
TEST(SmoothingChoice, ConsistentTargetsTakeTheSmallestWeight) {
  SynthesisProblem p;
  p.length_unit = 500;
  for (int k = 0; k < 50; ++k) p.targets.push_back({(k + 0.5) * kPi / 50, 1 / 500.0, 1.0});
  p.end_a = p.end_b = EndCondition::thesis_default(500);
  p.settings.smoothing_rule = SmoothingRule::shape_preserving;
  SmoothingChoice choice;
  const SynthesisResult r = synthesize_with_chosen_smoothing(p, choice);
  EXPECT_EQ(r.smoothing, 1e-10);
  EXPECT_EQ(choice.trials, 1);
  EXPECT_NEAR(r.profile(1.0), 500.0, 1e-9 * 500);
}

}  // namespace
}  // namespace polarform
