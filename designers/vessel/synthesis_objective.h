// The objective of the curvature synthesis in the scaled unknowns x = map⁻¹(ordinates) / L:
// J(x) = Σ w_k (κ̃(θ_k) − κ̃_k)² + λ ∫ (R̃''')² dθ with R̃ = R/L and κ̃ = κL (Bae 2002, §5.2; κ of
// DESIGN §4.4), its analytic gradient, the residuals' Jacobian and the Gauss–Newton Hessian.
// R''' is applied as differences of the ordinates, so a circle's smoothing term is exactly zero.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "designers/vessel/synthesis_problem.h"
#include "designers/vessel/synthesis_space.h"

namespace polarform {

class SynthesisObjective {
 public:
  SynthesisObjective(const SynthesisSpace& space, const std::vector<CurvatureTarget>& targets,
                     double length_unit, double smoothing);

  // κ̃(θ_k) − κ̃_k, and their derivatives with respect to x as the rows of *jacobian.
  Eigen::VectorXd residuals(const Eigen::VectorXd& x, Eigen::MatrixXd* jacobian) const;
  // Σ w_k (κ̃(θ_k) − κ̃_k)².
  double fit_term(const Eigen::VectorXd& x) const;
  // J(x) and, if asked, ∇J(x).
  double value(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const;
  // JᵀWJ + λ Dᵀ M D at x (J the residuals' Jacobian, D the map x → R''' ordinates).
  Eigen::MatrixXd gauss_newton_hessian(const Eigen::VectorXd& x) const;

 private:
  // R''' ordinates from ordinates: NURBS Book eq. (3.8) thrice, Q_i = p (P_{i+1} − P_i) /
  // (u_{i+p+1} − u_{i+1}), and its transpose.
  Eigen::VectorXd third_derivative(Eigen::VectorXd ordinates) const;
  Eigen::VectorXd third_derivative_transpose(Eigen::VectorXd g) const;

  Eigen::MatrixXd B0_, B1_, B2_;  // R̃, R̃', R̃'' at the targets as rows over x
  Eigen::VectorXd weights_, kappa_;
  Eigen::MatrixXd map_;           // ordinates over unknowns
  Eigen::VectorXd factors_[3];    // the difference factors of the three derivative rounds
  Eigen::MatrixXd gram_;          // ∫ N_i N_j dθ over [0, π] of R''''s basis
  double lambda_ = 0.0;
};

}  // namespace polarform
