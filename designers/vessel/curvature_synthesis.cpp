#include "designers/vessel/curvature_synthesis.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <nlopt.hpp>
#include <numbers>

#include "designers/vessel/head_volume.h"
#include "designers/vessel/nlopt_stop_reason.h"
#include "designers/vessel/polar_curvature.h"
#include "designers/vessel/synthesis_objective.h"
#include "designers/vessel/synthesis_space.h"
#include "src/error.h"
#include "src/fit/constrained_least_squares.h"
#include "src/nurbs/error_text.h"

namespace polarform {

namespace {

constexpr double kPi = std::numbers::pi;

// SLSQP's variables y with x = x0 + P y, P = L^{-T} for the Cholesky factor L Lᵀ = H0 of the
// Gauss–Newton Hessian H0 at the start (its diagonal raised by 1e-10 of its largest entry).
// SLSQP's initial identity Hessian is then the Gauss–Newton one: without it the first
// quasi-Newton steps overshoot from the circle into walls through the origin.
struct Whitened {
  const SynthesisObjective* f = nullptr;
  Eigen::VectorXd x0;
  Eigen::MatrixXd P;
  int evaluations = 0;

  Whitened(const SynthesisObjective& objective, Eigen::VectorXd start)
      : f(&objective), x0(std::move(start)) {
    Eigen::MatrixXd H = f->gauss_newton_hessian(x0);
    H.diagonal().array() += 1e-10 * H.diagonal().maxCoeff();
    const Eigen::LLT<Eigen::MatrixXd> llt(H);
    P = llt.matrixU().solve(Eigen::MatrixXd::Identity(H.rows(), H.cols()));
  }
  Eigen::VectorXd x(const double* y) const {
    return x0 + P * Eigen::Map<const Eigen::VectorXd>(y, x0.size());
  }
};

// Linear equalities rows · y = values.
struct Equalities {
  Eigen::MatrixXd rows;
  Eigen::VectorXd values;
};

double objective_callback(unsigned n, const double* y, double* grad, void* data) {
  auto* w = static_cast<Whitened*>(data);
  ++w->evaluations;
  Eigen::VectorXd g;
  const double value = w->f->value(w->x(y), grad ? &g : nullptr);
  if (grad) Eigen::Map<Eigen::VectorXd>(grad, n) = w->P.transpose() * g;
  return value;
}

void equality_callback(unsigned m, double* result, unsigned n, const double* y, double* grad,
                       void* data) {
  const auto* e = static_cast<Equalities*>(data);
  Eigen::Map<Eigen::VectorXd>(result, m) =
      e->rows * Eigen::Map<const Eigen::VectorXd>(y, n) - e->values;
  if (grad)  // row-major m x n
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(grad, m, n) =
        e->rows;
}

// The head's volume V(x0 + P y) = volume: one nonlinear equality, scaled by L³.
struct VolumeEquality {
  const HeadVolumeConstraint* volume = nullptr;
  const Whitened* w = nullptr;
  double value = 0.0;  // V / L³
};

double volume_callback(unsigned n, const double* y, double* grad, void* data) {
  const auto* e = static_cast<VolumeEquality*>(data);
  Eigen::VectorXd g;
  const double v = e->volume->value(e->w->x(y), grad ? &g : nullptr);
  if (grad) Eigen::Map<Eigen::VectorXd>(grad, n) = e->w->P.transpose() * g;
  return v - e->value;
}

std::string degrees(double rad) { return to_text(rad * 180 / kPi) + "°"; }

void validate(const SynthesisProblem& problem) {
  if (!(problem.length_unit > 0.0 && std::isfinite(problem.length_unit)))
    throw InputError("synthesis: length unit " + to_text(problem.length_unit) + " mm, expected > 0");
  if (problem.targets.empty())
    throw InputError("synthesis: no curvature targets, expected at least one (θ, κ)");
  if (problem.targets.size() > kMaxCurvatureTargets)
    throw InputError("synthesis: " + std::to_string(problem.targets.size()) +
                     " curvature targets, above the limit " + std::to_string(kMaxCurvatureTargets));
  for (std::size_t k = 0; k < problem.targets.size(); ++k) {
    const CurvatureTarget& t = problem.targets[k];
    const std::string which = "synthesis: curvature target " + std::to_string(k + 1);
    if (!(t.theta >= 0.0 && t.theta <= kPi))
      throw InputError(which + ": θ = " + degrees(t.theta) + " outside [0°, 180°]");
    if (!std::isfinite(t.kappa)) throw InputError(which + ": κ must be finite");
    if (!(t.weight > 0.0 && std::isfinite(t.weight)))
      throw InputError(which + ": weight " + to_text(t.weight) + ", expected > 0");
  }
}

// The smallest R on [0, π], on a grid of 64 samples per knot span.
std::pair<double, double> min_radius(const BSplineFunction& R) {
  double best = R(0.0), at = 0.0;
  const int samples = 64 * (R.size() - R.degree());
  for (int i = 1; i <= samples; ++i) {
    const double theta = kPi * i / samples, r = R(theta);
    if (r < best) best = r, at = theta;
  }
  return {best, at};
}

}  // namespace

// Bae 2002, §5.2 with eq. (5.5) as linear equality constraints; NLopt LD_SLSQP (Kraft 1988).
SynthesisResult synthesize_profile(const SynthesisProblem& problem) {
  validate(problem);
  const double L = problem.length_unit;
  const SynthesisSettings& settings = problem.settings;
  const SynthesisSpace space = synthesis_space(settings);
  const EndConstraints ends =
      end_constraints(space, problem.end_a, problem.end_b, L, problem.depth);
  const int m = space.unknowns();

  const SynthesisObjective f(space, problem.targets, L, settings.smoothing);

  // Start: the circle about the origin through the prescribed radii (else R = L), moved onto the
  // constraints by the smallest correction (Bae 2002, Appendix C).
  double start_radius = 0.0;
  int radii = 0;
  for (const EndCondition* c : {&problem.end_a, &problem.end_b})
    if (c->r) start_radius += *c->r / L, ++radii;
  start_radius = radii > 0 ? start_radius / radii : 1.0;
  const Eigen::VectorXd x0 = constrained_least_squares(
      Eigen::MatrixXd::Identity(m, m), Eigen::VectorXd::Constant(m, start_radius), ends.rows,
      ends.values / L);

  Whitened w(f, x0);
  Equalities eq{ends.rows * w.P, ends.values / L - ends.rows * x0};  // C(x0 + Py) = d
  nlopt::opt opt(nlopt::LD_SLSQP, static_cast<unsigned>(m));
  opt.set_min_objective(objective_callback, &w);
  if (eq.rows.rows() > 0)
    opt.add_equality_mconstraint(equality_callback, &eq,
                                 std::vector<double>(eq.rows.rows(), 1e-12));
  opt.set_xtol_rel(1e-13);
  opt.set_ftol_rel(1e-15);
  opt.set_maxeval(settings.max_iterations);

  const HeadVolumeConstraint volume(space);
  VolumeEquality volume_equality{&volume, &w, problem.volume ? *problem.volume / (L * L * L) : 0.0};
  if (problem.volume) {
    if (!(std::isfinite(*problem.volume) && *problem.volume > 0.0))
      throw InputError("synthesis: volume " + to_text(*problem.volume) + " mm³, expected > 0");
    opt.add_equality_constraint(volume_callback, &volume_equality, 1e-13);
  }

  std::vector<double> y(m, 0.0);
  double value = 0.0;
  nlopt::result status = nlopt::FAILURE;
  try {
    status = opt.optimize(y, value);
  } catch (const nlopt::roundoff_limited&) {
    status = nlopt::ROUNDOFF_LIMITED;
  } catch (const std::exception& e) {
    throw NumericalError(std::string("synthesis: NLopt SLSQP failed (") + e.what() + ") after " +
                         std::to_string(w.evaluations) + " evaluations");
  }
  const Eigen::VectorXd xv = w.x(y.data());

  SynthesisResult out;
  out.unknowns = m;
  out.smoothing = settings.smoothing;
  out.free_parameters = ends.free_parameters;
  out.iterations = w.evaluations;
  Eigen::VectorXd gradient;
  out.objective = f.value(xv, &gradient);
  out.fit_term = f.fit_term(xv);
  // The gradient projected on the null space of the constraints C: g − Cᵀ(CCᵀ)⁻¹Cg.
  const Eigen::MatrixXd& C = ends.rows;
  out.stationarity =
      C.rows() == 0 ? gradient.norm()
                    : (gradient - C.transpose() * (C * C.transpose()).ldlt().solve(C * gradient)).norm();
  const char* reason = nlopt_stop_reason(status);
  if (!reason)
    throw NumericalError(
        "synthesis: SLSQP did not converge within " + std::to_string(settings.max_iterations) +
        " evaluations (objective " + to_text(out.objective) + ", projected gradient " +
        to_text(out.stationarity) + "); raise <synthesis> max-iterations or smoothing");
  out.termination = reason;

  const Eigen::VectorXd ordinates = L * (space.map * xv);
  out.profile = BSplineFunction(space.degree, space.knots, ordinates);

  for (const CurvatureTarget& t : problem.targets) {
    const Eigen::VectorXd d = out.profile.derivatives(t.theta, 2);
    out.targets.push_back(
        {t.theta, t.kappa, polar_curvature(d(0), d(1), d(2)), t.weight, t.place, t.position});
  }
  for (const EndConstraint& c : ends.imposed) {
    const double achieved = out.profile.derivatives(c.theta(), c.order)(c.order);
    out.conditions.push_back({c.name(), c.value, achieved});
    out.max_violation = std::max(out.max_violation, std::abs(achieved - c.value));
  }
  if (out.max_violation > 1e-8 * L)
    throw NumericalError("synthesis: end conditions violated by up to " +
                         to_text(out.max_violation) + " after SLSQP (" + out.termination + ")");
  if (problem.volume) {
    const double achieved = volume.value(xv, nullptr) * L * L * L;
    out.conditions.push_back({"V", *problem.volume, achieved});
    if (std::abs(achieved - *problem.volume) > 1e-8 * *problem.volume)
      throw NumericalError("synthesis: the volume " + to_text(achieved) + " mm³ misses " +
                           to_text(*problem.volume) + " mm³ after SLSQP (" + out.termination +
                           "); the targets and end conditions may not allow it");
  }

  const auto [r_min, at] = min_radius(out.profile);
  out.min_radius = r_min;
  out.min_radius_angle = at;
  if (!(r_min > 0.0))
    throw NumericalError("synthesis: the solved profile has R(θ) = " + to_text(r_min) +
                         " mm <= 0 at θ = " + degrees(at) +
                         ": the curvature targets cannot be met by a wall around the axis");
  return out;
}

}  // namespace polarform
