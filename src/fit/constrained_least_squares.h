// Equality-constrained, weighted, optionally regularised linear least squares (Bae 2002,
// Appendix C), solved by the null-space method: no normal equations, no explicit inverses.
// The general facility behind cam B-spline segments and constrained curve/surface fitting; several
// right-hand sides (e.g. x, y, z coordinates) share one factorisation.
#pragma once

#include <Eigen/Core>

namespace polarform {

struct ConstrainedLsqOptions {
  // Row weights W = diag(weights), one per row of A, each >= 0; empty means W = I.
  Eigen::VectorXd weights;
  // Regularisation matrix R (n x n, symmetric positive semidefinite, e.g. a fairing Gram matrix);
  // empty means none. The objective gains lambda * trace(X^T R X).
  Eigen::MatrixXd regularization;
  double lambda = 0.0;
  // Relative threshold below which a pivot of a rank-revealing QR counts as zero.
  double rank_tolerance = 1e-12;
  // Relative residual of C X = D above which the constraints count as inconsistent.
  double constraint_tolerance = 1e-9;
};

// Minimises ||W^{1/2} (A X - B)||_F^2 + lambda * trace(X^T R X) subject to C X = D.
// A is k x n, B is k x r, C is m x n, D is m x r (r right-hand sides); pass 0-row matrices with the
// right column count for "no data rows" or "no constraints". A alone may be rank-deficient as long
// as A (with W and R) determines X on the null space of C.
// With rows(A) + rank(C) == n it solves the interpolation problem (C.5)-(C.6).
// Throws InputError on mismatched shapes, non-finite entries, negative weights or lambda, a
// non-symmetric or indefinite R, or inconsistent constraints (C X = D has no solution); throws
// NumericalError, stating the ranks, when the constrained problem is underdetermined.
Eigen::MatrixXd constrained_least_squares(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                          const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                                          const ConstrainedLsqOptions& options = {});

}  // namespace polarform
