// The input of the curvature synthesis of a vessel head (Bae 2002, §5.2): prescribed curvatures
// {(θ_k, κ_k)} with weights, the endpoint conditions (5.5) as any subset of R, R', R'' at each end,
// and the B-spline space of R(θ) on [0, π] (degree, ordinates, smoothing, optional symmetry about
// θ = π/2). Units: mm and radians (R' in mm/rad, R'' in mm/rad², κ in 1/mm).
#pragma once

#include <optional>
#include <vector>

namespace polarform {

// Where a target is given along the meridian: by the polar angle θ about the junction-plane
// centre (Bae's), by the arc length s from junction A (θ = 0), or by the meridian angle φ of the
// shell normal against the axis (90° at junction A, 0 at the apex, −90° at junction B).
enum class TargetPlace { polar_angle, arc_length, meridian_angle };

struct CurvatureTarget {
  double theta = 0.0;   // rad, in [0, π]; for the other places, where the design puts it
  double kappa = 0.0;   // 1/mm, positive where the wall turns towards the axis
  double weight = 1.0;  // > 0
  TargetPlace place = TargetPlace::polar_angle;
  double position = 0.0;  // s in mm or φ in rad (not used for the polar angle)

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

// How the smoothing weight λ is chosen: as given; the smallest λ whose curvature has no turning
// point or inflection the targets do not have (smoothing_choice.h); the largest λ that meets every
// target within kappa_tolerance.
enum class SmoothingRule { fixed, shape_preserving, tolerance };

struct SynthesisSettings {
  int degree = 5;       // of R(θ); >= 3 so that ∫(R''')² dθ is defined
  int ordinates = 20;   // control values; uniform clamped knots on [0, π]
  // λ of the smoothing term, dimensionless: the objective is scaled by the length unit L (the
  // vessel radius), Σ w_k (L(κ(θ_k) − κ_k))² + λ ∫ (R'''/L)² dθ, i.e. λ_mm = λ / L⁴.
  double smoothing = 1e-6;
  bool symmetric = false;     // R(π − θ) = R(θ): ordinates mirrored, half as many unknowns
  int max_iterations = 500;   // objective-and-gradient evaluations allowed to NLopt
  SmoothingRule smoothing_rule = SmoothingRule::fixed;  // the vessel designer's choice of λ
  double kappa_tolerance = 0.0;                         // 1/mm, for SmoothingRule::tolerance (> 0)

  bool operator==(const SynthesisSettings&) const = default;
};

struct SynthesisProblem {
  double length_unit = 1.0;  // L, mm: the scale of R (the vessel radius); > 0
  std::vector<CurvatureTarget> targets;
  EndCondition end_a;  // at θ = 0
  EndCondition end_b;  // at θ = π
  std::optional<double> depth;  // R(π/2), mm: the head's depth above the junction plane
  // mm³ enclosed by the head (the A half revolved) and its junction plane: (2π/3)∫₀^{π/2} R³cosθ dθ
  std::optional<double> volume;
  SynthesisSettings settings;
};

}  // namespace polarform
