// Curvature synthesis (Bae 2002, §5.2): circles come back as circles, the curvature of a known
// smooth polar curve gives that curve back, and contradictory conditions, too few degrees of
// freedom, non-convergence and a wall through the axis are each their own error.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "designers/vessel/curvature_synthesis.h"
#include "designers/vessel/polar_curvature.h"
#include "src/error.h"

namespace polarform {
namespace {

using ::testing::HasSubstr;
constexpr double kPi = std::numbers::pi;

std::string error_of(auto&& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

double max_deviation(const BSplineFunction& R, auto&& exact) {
  double worst = 0.0;
  for (int i = 0; i <= 2000; ++i) {
    const double theta = kPi * i / 2000;
    worst = std::max(worst, std::abs(R(theta) - exact(theta)));
  }
  return worst;
}

std::vector<CurvatureTarget> circle_targets(double radius, int count) {
  std::vector<CurvatureTarget> t;
  for (int k = 0; k < count; ++k) t.push_back({(k + 0.5) * kPi / count, 1 / radius, 1.0});
  return t;
}

TEST(CurvatureSynthesis, CircleWithCircleEndConditionsIsTheCircle) {
  SynthesisProblem problem;
  problem.length_unit = 500;
  problem.targets = circle_targets(500, 50);
  problem.end_a = problem.end_b = EndCondition::thesis_default(500);
  const SynthesisResult r = synthesize_profile(problem);
  EXPECT_LT(max_deviation(r.profile, [](double) { return 500.0; }), 1e-10 * 500);
  for (const TargetResidual& t : r.targets) EXPECT_LT(std::abs(t.residual()), 1e-15);
  ASSERT_EQ(r.conditions.size(), 6u);
  EXPECT_LT(r.max_violation, 1e-10);
  EXPECT_EQ(r.unknowns, 20);
  EXPECT_EQ(r.free_parameters, 14);
}

// A prescribed depth R(π/2) is one more linear equality: the hemisphere's targets on a 500 mm
// vessel with its default ends, held to a depth of 450 mm, reach it to 1e-8 of the radius and
// report it with the end conditions; a depth of 0 is refused by name.
TEST(CurvatureSynthesis, PrescribedDepthIsImposed) {
  SynthesisProblem problem;
  problem.length_unit = 500;
  problem.targets = circle_targets(500, 50);
  problem.end_a = problem.end_b = EndCondition::thesis_default(500);
  problem.depth = 450;
  const SynthesisResult r = synthesize_profile(problem);
  EXPECT_NEAR(r.profile(kPi / 2), 450.0, 1e-8 * 500);
  ASSERT_EQ(r.conditions.size(), 7u);
  EXPECT_EQ(r.conditions.back().name, "R(π/2)");
  EXPECT_LT(std::abs(r.conditions.back().violation()), 1e-8 * 500);
  EXPECT_EQ(r.free_parameters, 13);
  problem.depth = 0.0;
  EXPECT_THAT(error_of([&] { synthesize_profile(problem); }),
              HasSubstr("synthesis: depth R(π/2) 0 mm, expected > 0"));
}

// Only R' = R'' = 0 at the ends: the start circle (R = length unit 500) is wrong and the solver
// must find the radius 400 from the curvature alone (κ(0) = 1/R(0) when R' = R'' = 0).
TEST(CurvatureSynthesis, CircleRadiusFoundFromCurvature) {
  SynthesisProblem problem;
  problem.length_unit = 500;
  problem.targets = circle_targets(400, 50);
  problem.end_a = problem.end_b = EndCondition{std::nullopt, 0.0, 0.0};
  const SynthesisResult r = synthesize_profile(problem);
  EXPECT_LT(max_deviation(r.profile, [](double) { return 400.0; }), 1e-10 * 400);
  EXPECT_GT(r.iterations, 2);
  EXPECT_NEAR(r.min_radius, 400.0, 1e-7);
}

// R = 500 + A θ³(π − θ)³ (1 + θ/π): R, R', R'' match the circle's at both ends, not symmetric.
// Its curvature at 60 angles gives it back: with the default settings (quintic, λ = 1e-6, which
// cannot represent the degree-7 polynomial exactly) to 1e-6 relative (measured 1.5e-7), and in a
// degree-7 space without smoothing to round-off (measured 1.8e-15).
TEST(CurvatureSynthesis, RecoversKnownSmoothCurveFromItsCurvature) {
  const double A = 1.6;
  const auto R = [A](double t) { return 500 + A * std::pow(t * (kPi - t), 3) * (1 + t / kPi); };
  const auto derivatives = [A](double t, double* d) {  // R, R', R'' in closed form
    const double u = t * (kPi - t), du = kPi - 2 * t, g = 1 + t / kPi, dg = 1 / kPi;
    const double u3 = u * u * u, du3 = 3 * u * u * du, ddu3 = 6 * u * du * du - 6 * u * u;
    d[0] = 500 + A * u3 * g;
    d[1] = A * (du3 * g + u3 * dg);
    d[2] = A * (ddu3 * g + 2 * du3 * dg);
  };
  SynthesisProblem problem;
  problem.length_unit = 500;
  for (int k = 0; k < 60; ++k) {
    const double theta = (k + 0.5) * kPi / 60;
    double d[3];
    derivatives(theta, d);
    problem.targets.push_back({theta, polar_curvature(d[0], d[1], d[2]), 1.0});
  }
  problem.end_a = problem.end_b = EndCondition::thesis_default(500);
  const SynthesisResult quintic = synthesize_profile(problem);
  EXPECT_LT(max_deviation(quintic.profile, R) / 500, 1e-6);
  EXPECT_LT(quintic.max_violation, 1e-9);

  problem.settings.degree = 7;
  problem.settings.smoothing = 0.0;
  const SynthesisResult exact = synthesize_profile(problem);
  const double relative = max_deviation(exact.profile, R) / 500;
  EXPECT_LT(relative, 1e-12);
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", relative);
  RecordProperty("relative_deviation", text);
  double worst = 0.0;
  for (const TargetResidual& t : exact.targets) worst = std::max(worst, std::abs(t.residual()));
  EXPECT_LT(worst, 1e-14);
}

// Symmetric about π/2: R = 500 − A θ³(π − θ)³ (a flatter head), degree 6, 21 ordinates → 11
// unknowns, the ordinates mirror each other exactly.
TEST(CurvatureSynthesis, SymmetricProfile) {
  const double A = 0.8;
  const auto R = [A](double t) { return 500 - A * std::pow(t * (kPi - t), 3); };
  SynthesisProblem problem;
  problem.length_unit = 500;
  for (int k = 0; k < 40; ++k) {
    const double t = (k + 0.5) * kPi / 40, u = t * (kPi - t), du = kPi - 2 * t;
    problem.targets.push_back(
        {t, polar_curvature(R(t), -A * 3 * u * u * du, -A * (6 * u * du * du - 6 * u * u)), 1.0});
  }
  problem.end_a = problem.end_b = EndCondition::thesis_default(500);
  problem.settings = {6, 21, 0.0, true, 500};
  const SynthesisResult r = synthesize_profile(problem);
  EXPECT_EQ(r.unknowns, 11);
  EXPECT_EQ(r.free_parameters, 8);  // the B conditions repeat the A ones
  EXPECT_LT(max_deviation(r.profile, R) / 500, 1e-6);
  const Eigen::VectorXd c = r.profile.values();
  for (int i = 0; i < 21; ++i) EXPECT_EQ(c(i), c(20 - i));
}

TEST(CurvatureSynthesis, ContradictoryEndConditions) {
  SynthesisProblem problem;
  problem.length_unit = 500;
  problem.targets = circle_targets(500, 10);
  problem.end_a = EndCondition::thesis_default(500);
  problem.end_b = EndCondition::thesis_default(480);
  problem.settings.symmetric = true;
  EXPECT_EQ(error_of([&] { synthesize_profile(problem); }),
            "synthesis: contradictory end conditions: R(π) = 480 mm, but the B-spline space "
            "(degree 5, 20 ordinates, symmetric about θ = 90°) with R(0), R'(0), R''(0) forces "
            "R(π) = 500 mm");
  EXPECT_THROW(synthesize_profile(problem), InputError);

  // One cubic: R(0) = 500, R'(0) = R''(0) = 0 and R(π) = 480 force R = 500 − 20 θ³/π³, whose
  // slope at π is −60/π mm/rad, not the 0 asked for.
  problem.settings = {3, 4, 1e-6, false, 500};
  EXPECT_THAT(error_of([&] { synthesize_profile(problem); }),
              HasSubstr("R'(π) = 0 mm/rad, but the B-spline space (degree 3, 4 ordinates) with "
                        "R(0), R'(0), R''(0), R(π) forces R'(π) = -19.098593171 mm/rad"));
}

TEST(CurvatureSynthesis, TooFewDegreesOfFreedom) {
  SynthesisProblem problem;
  problem.length_unit = 500;
  problem.targets = circle_targets(500, 10);
  problem.end_a = problem.end_b = EndCondition::thesis_default(500);
  problem.settings = {5, 6, 1e-6, false, 500};
  EXPECT_EQ(error_of([&] { synthesize_profile(problem); }),
            "synthesis: too few degrees of freedom: 6 unknowns (degree 5, 6 ordinates) and 6 "
            "independent end conditions leave 0 free; use more ordinates or fewer end conditions");
  problem.settings = {5, 7, 1e-6, true, 500};  // 4 unknowns, 3 independent conditions: fine
  EXPECT_EQ(synthesize_profile(problem).free_parameters, 1);
  problem.settings = {5, 6, 1e-6, true, 500};
  EXPECT_THAT(error_of([&] { synthesize_profile(problem); }),
              HasSubstr("3 unknowns (degree 5, 6 ordinates, symmetric about θ = 90°) and 3 "
                        "independent end conditions leave 0 free"));
}

TEST(CurvatureSynthesis, NonConvergenceIsReported) {
  SynthesisProblem problem;
  problem.length_unit = 500;
  problem.targets = circle_targets(400, 50);
  problem.end_a = problem.end_b = EndCondition{std::nullopt, 0.0, 0.0};
  problem.settings.max_iterations = 3;
  const std::string message = error_of([&] { synthesize_profile(problem); });
  EXPECT_THAT(message, HasSubstr("synthesis: SLSQP did not converge within 3 evaluations (objective "));
  EXPECT_THAT(message, HasSubstr("projected gradient"));
  // Named as the project file spells it (<synthesis max-iterations>), not as the code does.
  EXPECT_THAT(message, HasSubstr("raise <synthesis> max-iterations or smoothing"));
  EXPECT_THROW(synthesize_profile(problem), NumericalError);
}

// Curvature 1/20 everywhere between ends at R = 100 (where R' = R'' = 0 make κ = 1/100): the best
// fit turns so tightly that the wall crosses the axis before θ = 90°.
TEST(CurvatureSynthesis, WallThroughTheAxisIsAnError) {
  SynthesisProblem problem;
  problem.length_unit = 100;
  problem.targets = circle_targets(20, 30);
  problem.end_a = problem.end_b = EndCondition::thesis_default(100);
  const std::string message = error_of([&] { synthesize_profile(problem); });
  EXPECT_THAT(message, HasSubstr("synthesis: the solved profile has R(θ) = -"));
  EXPECT_THAT(message, HasSubstr("mm <= 0 at θ = "));
}

TEST(CurvatureSynthesis, BadInput) {
  SynthesisProblem problem;
  problem.length_unit = 500;
  EXPECT_EQ(error_of([&] { synthesize_profile(problem); }),
            "synthesis: no curvature targets, expected at least one (θ, κ)");
  problem.targets = {{kPi + 0.1, 0.002, 1.0}};
  EXPECT_THAT(error_of([&] { synthesize_profile(problem); }),
              HasSubstr("curvature target 1: θ = 185.7"));
  problem.targets = {{1.0, 0.002, 0.0}};
  EXPECT_EQ(error_of([&] { synthesize_profile(problem); }),
            "synthesis: curvature target 1: weight 0, expected > 0");
  problem.targets = {{1.0, 0.002, 1.0}};
  problem.settings.degree = 2;
  EXPECT_EQ(error_of([&] { synthesize_profile(problem); }),
            "synthesis: degree 2 outside [3, 40] (∫(R''')² dθ needs degree >= 3)");
  problem.settings.degree = 5;
  problem.settings.ordinates = 5;
  EXPECT_EQ(error_of([&] { synthesize_profile(problem); }),
            "synthesis: ordinates 5, expected in [degree + 1 = 6, 400]");
  // Limits checked before anything the size of the input is allocated.
  problem.settings.ordinates = 1000000;
  EXPECT_EQ(error_of([&] { synthesize_profile(problem); }),
            "synthesis: ordinates 1000000, expected in [degree + 1 = 6, 400]");
  problem.settings.ordinates = 20;
  problem.settings.max_iterations = 1000000000;
  EXPECT_EQ(error_of([&] { synthesize_profile(problem); }),
            "synthesis: max-iterations 1000000000, expected in [1, 10000]");
  problem.settings.max_iterations = 500;
  problem.targets.assign(kMaxCurvatureTargets + 1, {1.0, 0.002, 1.0});
  EXPECT_EQ(error_of([&] { synthesize_profile(problem); }),
            "synthesis: 20001 curvature targets, above the limit 20000");
}

}  // namespace
}  // namespace polarform
