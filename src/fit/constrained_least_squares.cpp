#include "src/fit/constrained_least_squares.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <cmath>
#include <sstream>
#include <string>

#include "src/error.h"

namespace polarform {
namespace {

std::string shape(const Eigen::MatrixXd& M) {
  return std::to_string(M.rows()) + " x " + std::to_string(M.cols());
}

void check_inputs(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C,
                  const Eigen::MatrixXd& D, const ConstrainedLsqOptions& o) {
  const auto fail = [](const std::string& why) {
    throw InputError("constrained least squares: " + why);
  };
  const Eigen::Index n = A.cols();
  if (n == 0) fail("A has no columns (no unknowns)");
  if (B.rows() != A.rows()) fail("B is " + shape(B) + ", expected " + std::to_string(A.rows()) + " rows like A");
  if (C.cols() != n) fail("C is " + shape(C) + ", expected " + std::to_string(n) + " columns like A");
  if (D.rows() != C.rows()) fail("D is " + shape(D) + ", expected " + std::to_string(C.rows()) + " rows like C");
  if (D.cols() != B.cols()) fail("B has " + std::to_string(B.cols()) + " right-hand sides but D has " + std::to_string(D.cols()));
  if (!A.allFinite() || !B.allFinite() || !C.allFinite() || !D.allFinite())
    fail("A, B, C or D has a non-finite entry");
  if (o.weights.size() != 0) {
    if (o.weights.size() != A.rows())
      fail("weights has " + std::to_string(o.weights.size()) + " entries, expected one per row of A (" +
           std::to_string(A.rows()) + ")");
    if (!o.weights.allFinite() || (o.weights.array() < 0).any()) fail("weights must be finite and >= 0");
  }
  if (!(o.lambda >= 0) || !std::isfinite(o.lambda)) fail("lambda must be finite and >= 0");
  if (o.regularization.size() != 0) {
    const Eigen::MatrixXd& R = o.regularization;
    if (R.rows() != n || R.cols() != n) fail("regularization is " + shape(R) + ", expected " + std::to_string(n) + " x " + std::to_string(n));
    if (!R.allFinite()) fail("regularization has a non-finite entry");
    if ((R - R.transpose()).cwiseAbs().maxCoeff() > 1e-12 * std::max(1.0, R.cwiseAbs().maxCoeff()))
      fail("regularization matrix is not symmetric");
  }
}

// F with F^T F = R for a symmetric positive semidefinite R, from its eigendecomposition
// R = V diag(mu) V^T: F = diag(sqrt(mu)) V^T, keeping the rows of the nonzero eigenvalues.
Eigen::MatrixXd psd_factor(const Eigen::MatrixXd& R) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(R);
  if (eig.info() != Eigen::Success)
    throw NumericalError("constrained least squares: eigendecomposition of the regularization matrix failed");
  const Eigen::VectorXd& mu = eig.eigenvalues();  // increasing
  const double scale = std::max(mu.cwiseAbs().maxCoeff(), 1e-300);
  if (mu(0) < -1e-10 * scale)
    throw InputError("constrained least squares: regularization matrix is not positive semidefinite "
                     "(eigenvalue " + std::to_string(mu(0)) + ")");
  Eigen::Index first = 0;
  while (first < mu.size() && mu(first) <= 1e-14 * scale) ++first;
  const Eigen::Index rank = mu.size() - first;
  return mu.tail(rank).cwiseSqrt().asDiagonal() * eig.eigenvectors().rightCols(rank).transpose();
}

}  // namespace

// Bae 2002, Appendix C (eqs. C.7-C.8), solved by the null-space method: Golub & Van Loan,
// Matrix Computations, the LSE problem (QR of C^T splits x into a particular and a null-space part).
Eigen::MatrixXd constrained_least_squares(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B,
                                          const Eigen::MatrixXd& C, const Eigen::MatrixXd& D,
                                          const ConstrainedLsqOptions& options) {
  check_inputs(A, B, C, D, options);
  const Eigen::Index n = A.cols(), m = C.rows(), rhs = B.cols();

  // X = Q1 Y1 + Q2 Y2 with C^T Pi = Q R: Y1 is fixed by the constraints, Q2 spans null(C).
  Eigen::MatrixXd X_particular = Eigen::MatrixXd::Zero(n, rhs);
  Eigen::MatrixXd Z = Eigen::MatrixXd::Identity(n, n);
  Eigen::Index rank_c = 0;
  if (m > 0) {
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(C.transpose());
    qr.setThreshold(options.rank_tolerance);
    rank_c = qr.rank();
    const Eigen::MatrixXd Q = qr.householderQ();
    const Eigen::MatrixXd D_permuted = qr.colsPermutation().transpose() * D;
    const Eigen::MatrixXd R11 = qr.matrixQR().topLeftCorner(rank_c, rank_c);
    const Eigen::MatrixXd Y1 =
        R11.transpose().triangularView<Eigen::Lower>().solve(D_permuted.topRows(rank_c));
    X_particular = Q.leftCols(rank_c) * Y1;
    Z = Q.rightCols(n - rank_c);
    const double residual = (C * X_particular - D).cwiseAbs().maxCoeff();
    const double scale = C.cwiseAbs().maxCoeff() * X_particular.cwiseAbs().maxCoeff() +
                         D.cwiseAbs().maxCoeff();
    if (residual > options.constraint_tolerance * std::max(scale, 1e-300)) {
      std::ostringstream msg;
      msg << "constrained least squares: the constraints C x = d are inconsistent (C has rank "
          << rank_c << " for " << m << " rows; best residual " << residual << ")";
      throw InputError(msg.str());
    }
  }
  const Eigen::Index free = n - rank_c;
  if (free == 0) return X_particular;

  // Reduced problem for Y2: [W^{1/2} A Z; sqrt(lambda) F Z] Y2 = [W^{1/2}(B - A Xp); -sqrt(lambda) F Xp].
  const bool regularized = options.regularization.size() != 0 && options.lambda > 0;
  const Eigen::MatrixXd F = regularized ? psd_factor(options.regularization) : Eigen::MatrixXd(0, n);
  const double sqrt_lambda = std::sqrt(options.lambda);
  const Eigen::Index k = A.rows(), f = F.rows();
  Eigen::MatrixXd M(k + f, free), rhs_reduced(k + f, rhs);
  M.topRows(k) = A * Z;
  rhs_reduced.topRows(k) = B - A * X_particular;
  if (options.weights.size() != 0) {
    const Eigen::VectorXd sqrt_w = options.weights.cwiseSqrt();
    M.topRows(k) = sqrt_w.asDiagonal() * M.topRows(k);
    rhs_reduced.topRows(k) = sqrt_w.asDiagonal() * rhs_reduced.topRows(k);
  }
  if (f > 0) {
    M.bottomRows(f) = sqrt_lambda * (F * Z);
    rhs_reduced.bottomRows(f) = -sqrt_lambda * (F * X_particular);
  }
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(M);
  qr.setThreshold(options.rank_tolerance);
  const Eigen::Index rank_objective = M.rows() == 0 ? 0 : qr.rank();
  if (rank_objective < free) {
    std::ostringstream msg;
    msg << "constrained least squares: underdetermined — " << n << " unknowns, constraints of rank "
        << rank_c << " leave " << free << " free, but the objective has rank only " << rank_objective
        << " on them";
    throw NumericalError(msg.str());
  }
  return X_particular + Z * qr.solve(rhs_reduced);
}

}  // namespace polarform
