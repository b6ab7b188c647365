#include "designers/vessel/smoothing_choice.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

#include "designers/vessel/polar_curvature.h"
#include "src/error.h"

namespace polarform {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSmallest = 1e-10, kLargest = 1e4;
constexpr int kBisections = 5;  // the bracket's decade to a factor 10^(1/32) ≈ 1.07

// Turning points of a sequence with hysteresis h: a reversal counts once the sequence has moved
// more than h back from its running extreme.
int turning_points(const std::vector<double>& values, double h) {
  int count = 0, direction = 0;
  double extreme = values.empty() ? 0.0 : values.front();
  for (double v : values) {
    if (direction >= 0 && v < extreme - h) {
      if (direction > 0) ++count;
      direction = -1, extreme = v;
    } else if (direction <= 0 && v > extreme + h) {
      if (direction < 0) ++count;
      direction = 1, extreme = v;
    } else if ((direction > 0 && v > extreme) || (direction < 0 && v < extreme)) {
      extreme = v;
    }
  }
  return count;
}

struct TargetShape {
  int turning_points = 0;
  double hysteresis = 0.0;
  bool positive = true;  // every target (and prescribed end curvature) > 0
};

// The targets' sequence in θ (duplicates averaged), with the curvature an end's R, R', R'' fix.
TargetShape target_shape(const SynthesisProblem& problem) {
  std::map<double, std::pair<double, int>> by_theta;
  for (const CurvatureTarget& t : problem.targets) {
    auto& [sum, n] = by_theta[t.theta];
    sum += t.kappa, ++n;
  }
  const auto end_kappa = [&](const EndCondition& c, double theta) {
    if (c.r && c.dr && c.ddr && !by_theta.count(theta))
      by_theta[theta] = {polar_curvature(*c.r, *c.dr, *c.ddr), 1};
  };
  end_kappa(problem.end_a, 0.0);
  end_kappa(problem.end_b, kPi);
  std::vector<double> kappa;
  for (const auto& [theta, s] : by_theta) kappa.push_back(s.first / s.second);
  const auto [lo, hi] = std::minmax_element(kappa.begin(), kappa.end());
  TargetShape out;
  out.hysteresis = 0.01 * std::max(*hi - *lo, 1e-3 * std::max(std::abs(*lo), std::abs(*hi)));
  out.turning_points = turning_points(kappa, out.hysteresis);
  out.positive = *lo > 0.0;
  return out;
}

struct Trial {
  double lambda = 0.0;
  bool ok = false;  // synthesised without error
  bool passes = false;
  SynthesisResult result;
  int turning_points = 0;
  double max_residual = 0.0;
};

class Chooser {
 public:
  Chooser(const SynthesisProblem& problem) : problem_(problem), shape_(target_shape(problem)) {}

  Trial run(double lambda) {
    ++trials_;
    Trial t;
    t.lambda = lambda;
    SynthesisProblem p = problem_;
    p.settings.smoothing = lambda;
    try {
      t.result = synthesize_profile(p);
      t.ok = true;
    } catch (const NumericalError& e) {
      last_error_ = e.what();
      return t;
    }
    for (const TargetResidual& r : t.result.targets)
      t.max_residual = std::max(t.max_residual, std::abs(r.residual()));
    std::vector<double> kappa;
    double smallest = 1e300;
    for (int i = 0; i <= 720; ++i) {
      const Eigen::VectorXd d = t.result.profile.derivatives(kPi * i / 720, 2);
      kappa.push_back(polar_curvature(d(0), d(1), d(2)));
      smallest = std::min(smallest, kappa.back());
    }
    t.turning_points = turning_points(kappa, shape_.hysteresis);
    if (problem_.settings.smoothing_rule == SmoothingRule::tolerance)
      t.passes = t.max_residual <= problem_.settings.kappa_tolerance;
    else
      t.passes = t.turning_points <= shape_.turning_points && (!shape_.positive || smallest > 0.0);
    return t;
  }

  int trials() const { return trials_; }
  const TargetShape& shape() const { return shape_; }
  const std::string& last_error() const { return last_error_; }

 private:
  const SynthesisProblem& problem_;
  TargetShape shape_;
  int trials_ = 0;
  std::string last_error_;
};

// Walks the decades from `start` towards the answer of the rule, then bisects the bracket.
SynthesisResult search_smoothing(const SynthesisProblem& problem, SmoothingChoice& choice,
                                 double start) {
  const SmoothingRule rule = problem.settings.smoothing_rule;
  choice = SmoothingChoice{rule};
  Chooser chooser(problem);
  // Shape-preserving wants the smallest passing λ, tolerance the largest: walk the decades from
  // `start` towards the other end until the answer flips.
  const bool smallest = rule == SmoothingRule::shape_preserving;
  std::optional<Trial> pass, fail;
  Trial first = chooser.run(start);
  // Shape-preserving: passes at start → look downwards for the first failure; fails → upwards.
  // Tolerance: passes → upwards for the first failure; fails → downwards for the first pass.
  // A weight that did not converge (a tiny one, usually) is left upwards.
  const bool up = !first.ok || (smallest ? !first.passes : first.passes);
  Trial previous = std::move(first);
  for (double lambda = up ? start * 10 : start / 10;
       lambda >= kSmallest * 0.99 && lambda <= kLargest * 1.01;
       lambda = up ? lambda * 10 : lambda / 10) {
    Trial t = chooser.run(lambda);
    if (!t.ok) continue;
    if (previous.ok && t.passes != previous.passes) {
      (t.passes ? pass : fail) = std::move(t);
      (previous.passes ? pass : fail) = std::move(previous);
      break;
    }
    previous = std::move(t);
  }
  if (!pass || !fail) {
    // No flip: every λ passes (take the end the rule favours) or none does (take the last tried).
    Trial& only = previous;
    if (!only.ok)
      throw NumericalError(chooser.last_error() +
                           " (at every smoothing weight tried, 1e-10 to 1e4)");
    choice.met = only.passes;
    choice.trials = chooser.trials();
    choice.target_turning_points = chooser.shape().turning_points;
    choice.turning_points = only.turning_points, choice.max_residual = only.max_residual;
    return std::move(only.result);
  }
  for (int k = 0; k < kBisections; ++k) {
    Trial t = chooser.run(std::sqrt(pass->lambda * fail->lambda));
    if (!t.ok) break;
    (t.passes ? pass : fail) = std::move(t);
  }
  choice.trials = chooser.trials();
  choice.target_turning_points = chooser.shape().turning_points;
  choice.turning_points = pass->turning_points, choice.max_residual = pass->max_residual;
  return std::move(pass->result);
}

}  // namespace

const char* smoothing_rule_name(SmoothingRule rule) {
  switch (rule) {
    case SmoothingRule::shape_preserving:
      return "shape-preserving";
    case SmoothingRule::tolerance:
      return "tolerance";
    case SmoothingRule::fixed:
      break;
  }
  return "fixed";
}

SynthesisResult synthesize_with_chosen_smoothing(const SynthesisProblem& problem,
                                                 SmoothingChoice& choice,
                                                 std::optional<double> hint) {
  const SmoothingRule rule = problem.settings.smoothing_rule;
  if (rule == SmoothingRule::tolerance && !(problem.settings.kappa_tolerance > 0.0))
    throw InputError("synthesis: the tolerance rule needs kappa-tolerance > 0 (1/mm)");
  if (rule == SmoothingRule::fixed) {
    choice = SmoothingChoice{rule};
    SynthesisResult r = synthesize_profile(problem);
    choice.trials = 1;
    for (const TargetResidual& t : r.targets)
      choice.max_residual = std::max(choice.max_residual, std::abs(t.residual()));
    return r;
  }
  if (hint) {  // from the hint's decade first; without a bracket there, over the whole range
    SynthesisResult r = search_smoothing(
        problem, choice,
        std::clamp(std::pow(10.0, std::floor(std::log10(*hint))), kSmallest, kLargest));
    if (choice.met) return r;
  }
  return search_smoothing(problem, choice, kSmallest);
}

}  // namespace polarform
