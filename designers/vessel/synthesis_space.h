// The unknowns of the curvature synthesis: R(θ) as a clamped B-spline on uniform knots over [0, π]
// whose ordinates are a linear map of the unknowns (the identity, or mirrored pairs for a profile
// symmetric about θ = π/2), and the endpoint conditions (Bae 2002, eq. (5.5)) as independent linear
// equalities on those unknowns — contradictory or over-constraining condition sets are reported
// here, before any optimisation, with the numbers that conflict.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "designers/vessel/synthesis_problem.h"
#include "src/nurbs/knots.h"

namespace polarform {

struct SynthesisSpace {
  int degree = 0;
  Knots knots;          // uniform clamped on [0, π]
  Eigen::MatrixXd map;  // ordinates = map · unknowns (ordinates x unknowns)
  int ordinates() const { return static_cast<int>(map.rows()); }
  int unknowns() const { return static_cast<int>(map.cols()); }
};

// Throws InputError naming the setting unless 3 <= degree <= kMaxDegree, ordinates >= degree + 1,
// smoothing >= 0 and max_iterations >= 1.
SynthesisSpace synthesis_space(const SynthesisSettings& settings);

// One imposed condition: R^(order) at θ = 0 (end A) or π (end B), or the depth R(π/2) (M).
struct EndConstraint {
  char end = 'A';       // 'A', 'B' or 'M'
  int order = 0;        // 0: R, 1: R', 2: R''
  double value = 0.0;   // mm, mm/rad, mm/rad²
  Eigen::RowVectorXd row;  // the condition as row · unknowns = value
  std::string name() const;  // e.g. "R''(π)"
  double theta() const;      // rad
};

struct EndConstraints {
  std::vector<EndConstraint> imposed;  // every condition, end A then B, R then R' then R''
  Eigen::MatrixXd rows;                // an independent subset spanning all of them
  Eigen::VectorXd values;
  int free_parameters = 0;  // unknowns − rank
};

// The end conditions, then the depth R(π/2) = depth when given (a head of prescribed depth).
// Throws InputError if a condition contradicts the ones before it in the space (naming both
// values), or if the independent conditions leave no free parameter. length_unit (mm) scales the
// tolerance of the consistency check.
EndConstraints end_constraints(const SynthesisSpace& space, const EndCondition& end_a,
                               const EndCondition& end_b, double length_unit,
                               std::optional<double> depth = std::nullopt);

}  // namespace polarform
