// The input of the curvature synthesis of a vessel head (Bae 2002, §5.2): prescribed curvatures
// {(θ_k, κ_k)} with weights, the endpoint conditions (5.5) as any subset of R, R', R'' at each end,
// and the B-spline space of R(θ) on [0, π] (degree, ordinates, smoothing, optional symmetry about
// θ = π/2). Units: mm and radians (R' in mm/rad, R'' in mm/rad², κ in 1/mm).
#pragma once

#include <optional>
#include <vector>

namespace polarform {

struct CurvatureTarget {
  double theta = 0.0;   // rad, in [0, π]
  double kappa = 0.0;   // 1/mm, positive where the wall turns towards the axis
  double weight = 1.0;  // > 0

  bool operator==(const CurvatureTarget&) const = default;
};

// The conditions imposed at one end (A: θ = 0, B: θ = π); an empty optional leaves it free.
struct EndCondition {
  std::optional<double> r;    // R, mm
  std::optional<double> dr;   // R', mm/rad
  std::optional<double> ddr;  // R'', mm/rad²

  // Bae 2002, eq. (5.5): R = radius, R' = R'' = 0 (curvature 1/radius at the end).
  static EndCondition thesis_default(double radius) { return {radius, 0.0, 0.0}; }
  bool operator==(const EndCondition&) const = default;
};

// Input limits, checked before any allocation: the dense synthesis (targets x ordinates matrices,
// an NLopt run of max_iterations evaluations) stays within seconds and tens of MB at the limits.
constexpr int kMaxOrdinates = 400;
constexpr int kMaxSynthesisIterations = 10000;
constexpr int kMaxCurvatureTargets = 20000;

struct SynthesisSettings {
  int degree = 5;       // of R(θ); >= 3 so that ∫(R''')² dθ is defined
  int ordinates = 20;   // control values; uniform clamped knots on [0, π]
  // λ of the smoothing term, dimensionless: the objective is scaled by the length unit L (the
  // vessel radius), Σ w_k (L(κ(θ_k) − κ_k))² + λ ∫ (R'''/L)² dθ, i.e. λ_mm = λ / L⁴.
  double smoothing = 1e-6;
  bool symmetric = false;     // R(π − θ) = R(θ): ordinates mirrored, half as many unknowns
  int max_iterations = 500;   // objective-and-gradient evaluations allowed to NLopt

  bool operator==(const SynthesisSettings&) const = default;
};

struct SynthesisProblem {
  double length_unit = 1.0;  // L, mm: the scale of R (the vessel radius); > 0
  std::vector<CurvatureTarget> targets;
  EndCondition end_a;  // at θ = 0
  EndCondition end_b;  // at θ = π
  std::optional<double> depth;  // R(π/2), mm: the head's depth above the junction plane
  SynthesisSettings settings;
};

}  // namespace polarform
