// Curvature synthesis of a vessel head (Bae 2002, §5.2): the B-spline R(θ) on [0, π] minimising
// Σ w_k (κ(θ_k) − κ_k)² + λ ∫ (R''')² dθ (κ of DESIGN §4.4, scaled as in SynthesisSettings) subject
// to the endpoint conditions (5.5) and a depth as linear equalities and a volume as a cubic one
// (head_volume.h), by NLopt's SLSQP with analytic gradients,
// started from the circle through the prescribed end radii. Everything reported is measured on the
// result: curvature residuals per target, condition violations, stationarity, the smallest R.
#pragma once

#include <string>
#include <vector>

#include "designers/vessel/synthesis_problem.h"
#include "src/nurbs/bspline.h"

namespace polarform {

struct TargetResidual {
  double theta = 0.0;     // rad
  double target = 0.0;    // κ_k, 1/mm
  double achieved = 0.0;  // κ(θ_k), 1/mm
  double weight = 1.0;
  TargetPlace place = TargetPlace::polar_angle;
  double position = 0.0;  // s in mm or φ in rad, as given (CurvatureTarget)
  double residual() const { return achieved - target; }
};

struct ConditionViolation {
  std::string name;         // "R(0)", "R'(π)", …, "R(π/2)" (depth), "V" (volume)
  double prescribed = 0.0;  // mm, mm/rad, mm/rad² or mm³
  double achieved = 0.0;
  double violation() const { return achieved - prescribed; }
};

struct SynthesisResult {
  BSplineFunction profile;  // R(θ), mm, on [0, π]
  std::vector<TargetResidual> targets;
  std::vector<ConditionViolation> conditions;  // every imposed end condition
  double smoothing = 0.0;    // λ as used (dimensionless, SynthesisSettings::smoothing)
  int unknowns = 0;          // after the symmetry map
  int free_parameters = 0;   // unknowns minus independent end conditions
  int iterations = 0;        // objective-and-gradient evaluations by NLopt
  std::string termination;   // NLopt's reason for stopping
  double objective = 0.0;    // the scaled objective at the result (dimensionless)
  double fit_term = 0.0;     // its curvature part Σ w_k (L(κ(θ_k) − κ_k))²
  double stationarity = 0.0; // |∇J| projected on the constraints' null space, scaled units
  double max_violation = 0.0;  // largest |violation| of a condition (mm, mm/rad, mm/rad²)
  double min_radius = 0.0;   // smallest R(θ), mm, on 64 samples per knot span (> 0, else error)
  double min_radius_angle = 0.0;
};

// Throws InputError for bad input (no targets, a target outside [0, π] or with weight <= 0,
// settings out of range, contradictory end conditions, too few degrees of freedom) and
// NumericalError when SLSQP does not converge within settings.max_iterations, fails, leaves a
// condition violated, or the result has R(θ) <= 0 somewhere.
SynthesisResult synthesize_profile(const SynthesisProblem& problem);

}  // namespace polarform
