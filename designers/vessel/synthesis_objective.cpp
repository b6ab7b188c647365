#include "designers/vessel/synthesis_objective.h"

#include <numbers>

#include "designers/vessel/polar_curvature.h"
#include "src/fit/fairness.h"
#include "src/nurbs/basis.h"

namespace polarform {

SynthesisObjective::SynthesisObjective(const SynthesisSpace& space,
                                       const std::vector<CurvatureTarget>& targets,
                                       double length_unit, double smoothing)
    : map_(space.map), lambda_(smoothing) {
  const int p = space.degree, n = space.ordinates(), K = static_cast<int>(targets.size());
  B0_ = B1_ = B2_ = Eigen::MatrixXd::Zero(K, n);
  weights_.resize(K);
  kappa_.resize(K);
  for (int k = 0; k < K; ++k) {
    const CurvatureTarget& t = targets[k];
    const int span = find_span(p, space.knots, n, t.theta);
    const Eigen::MatrixXd d = ders_basis_funs(span, t.theta, p, 2, space.knots);
    B0_.block(k, span - p, 1, p + 1) = d.row(0);
    B1_.block(k, span - p, 1, p + 1) = d.row(1);
    B2_.block(k, span - p, 1, p + 1) = d.row(2);
    weights_(k) = t.weight;
    kappa_(k) = t.kappa * length_unit;
  }
  B0_ *= map_;
  B1_ *= map_;
  B2_ *= map_;

  Knots knots = space.knots;
  for (int level = 0, degree = p; level < 3; ++level, --degree) {
    const int size = static_cast<int>(knots.size()) - degree - 1;
    factors_[level].resize(size - 1);
    for (int i = 0; i + 1 < size; ++i)
      factors_[level](i) = degree / (knots[i + degree + 1] - knots[i + 1]);
    knots = Knots(knots.begin() + 1, knots.end() - 1);
  }
  // derivative_gram integrates over the domain mapped to [0, 1]: ∫ dθ = π ∫ ds.
  gram_ = std::numbers::pi * derivative_gram(SplineAxis{p - 3, knots, false}, 0);
}

Eigen::VectorXd SynthesisObjective::third_derivative(Eigen::VectorXd v) const {
  for (const Eigen::VectorXd& f : factors_) {
    const Eigen::VectorXd differences = v.tail(v.size() - 1) - v.head(v.size() - 1);
    v = f.cwiseProduct(differences);
  }
  return v;
}

Eigen::VectorXd SynthesisObjective::third_derivative_transpose(Eigen::VectorXd g) const {
  for (int level = 2; level >= 0; --level) {
    const Eigen::VectorXd fg = factors_[level].cwiseProduct(g);
    g = Eigen::VectorXd::Zero(fg.size() + 1);
    g.tail(fg.size()) += fg;
    g.head(fg.size()) -= fg;
  }
  return g;
}

// κ and its partial derivatives from DESIGN §4.4, chained through R^(i) = B_i x.
Eigen::VectorXd SynthesisObjective::residuals(const Eigen::VectorXd& x,
                                              Eigen::MatrixXd* jacobian) const {
  const Eigen::VectorXd r = B0_ * x, dr = B1_ * x, ddr = B2_ * x;
  Eigen::VectorXd e(r.size());
  if (jacobian) jacobian->resize(r.size(), x.size());
  for (Eigen::Index k = 0; k < r.size(); ++k) {
    const PolarCurvature c = polar_curvature_with_gradient(r(k), dr(k), ddr(k));
    e(k) = c.kappa - kappa_(k);
    if (jacobian) jacobian->row(k) = c.d_r * B0_.row(k) + c.d_dr * B1_.row(k) + c.d_ddr * B2_.row(k);
  }
  return e;
}

double SynthesisObjective::fit_term(const Eigen::VectorXd& x) const {
  const Eigen::VectorXd e = residuals(x, nullptr);
  return e.dot(weights_.cwiseProduct(e));
}

double SynthesisObjective::value(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const {
  Eigen::MatrixXd J;
  const Eigen::VectorXd e = residuals(x, gradient ? &J : nullptr);
  const Eigen::VectorXd d = third_derivative(map_ * x), Md = gram_ * d;
  if (gradient)
    *gradient = 2 * (J.transpose() * weights_.cwiseProduct(e) +
                     lambda_ * map_.transpose() * third_derivative_transpose(Md));
  return e.dot(weights_.cwiseProduct(e)) + lambda_ * d.dot(Md);
}

Eigen::MatrixXd SynthesisObjective::gauss_newton_hessian(const Eigen::VectorXd& x) const {
  Eigen::MatrixXd J;
  residuals(x, &J);
  Eigen::MatrixXd D(gram_.rows(), map_.cols());
  for (Eigen::Index j = 0; j < map_.cols(); ++j) D.col(j) = third_derivative(map_.col(j));
  return J.transpose() * weights_.asDiagonal() * J + lambda_ * D.transpose() * gram_ * D;
}

}  // namespace polarform
