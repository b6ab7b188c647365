// Constrained least squares (Bae 2002, Appendix C) against closed forms, the KKT system (C.8) and the
// interpolation case (C.5)-(C.6); error reporting for inconsistent and underdetermined problems.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <random>

#include "src/error.h"
#include "src/fit/constrained_least_squares.h"

namespace polarform {
namespace {

Eigen::MatrixXd random_matrix(int rows, int cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd M(rows, cols);
  for (int i = 0; i < rows; ++i)
    for (int j = 0; j < cols; ++j) M(i, j) = u(rng);
  return M;
}

// The KKT system of (C.8) with weights and regularisation, solved by full-pivot LU (test oracle).
Eigen::MatrixXd kkt_solution(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, const Eigen::MatrixXd& C,
                             const Eigen::MatrixXd& D, const Eigen::VectorXd& w, const Eigen::MatrixXd& R,
                             double lambda) {
  const Eigen::Index n = A.cols(), m = C.rows();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + m, n + m), rhs(n + m, B.cols());
  K.topLeftCorner(n, n) = A.transpose() * w.asDiagonal() * A + lambda * R;
  K.topRightCorner(n, m) = C.transpose();
  K.bottomLeftCorner(m, n) = C;
  rhs.topRows(n) = A.transpose() * w.asDiagonal() * B;
  rhs.bottomRows(m) = D;
  return Eigen::FullPivLU<Eigen::MatrixXd>(K).solve(rhs).topRows(n);
}

// min ||x - b||^2 subject to sum(x) = 1 has x = b - (sum(b) - 1)/n (projection onto a hyperplane).
TEST(ConstrainedLsq, ProjectionOntoHyperplane) {
  const int n = 7;
  const Eigen::VectorXd b = random_matrix(n, 1, 3);
  const Eigen::MatrixXd x = constrained_least_squares(Eigen::MatrixXd::Identity(n, n), b,
                                                      Eigen::MatrixXd::Ones(1, n), Eigen::MatrixXd::Ones(1, 1));
  const Eigen::VectorXd expected = b.array() - (b.sum() - 1.0) / n;
  EXPECT_LT((x - expected).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(x.sum(), 1.0, 1e-14);
}

// Without constraints a weighted fit of a constant is the weighted mean; with R = I and A = I the
// regularised solution is b / (1 + lambda). Two right-hand sides at once.
TEST(ConstrainedLsq, WeightedMeanAndRidgeClosedForms) {
  const Eigen::VectorXd data = (Eigen::VectorXd(4) << 1.0, 2.0, 4.0, 8.0).finished();
  ConstrainedLsqOptions o;
  o.weights = (Eigen::VectorXd(4) << 1.0, 3.0, 0.0, 2.0).finished();
  Eigen::MatrixXd B(4, 2);
  B << data, -2.0 * data;
  const Eigen::MatrixXd x = constrained_least_squares(Eigen::MatrixXd::Ones(4, 1), B, Eigen::MatrixXd(0, 1),
                                                      Eigen::MatrixXd(0, 2), o);
  const double mean = (1.0 * 1 + 3.0 * 2 + 0.0 * 4 + 2.0 * 8) / 6.0;
  EXPECT_NEAR(x(0, 0), mean, 1e-14);
  EXPECT_NEAR(x(0, 1), -2.0 * mean, 1e-14);

  ConstrainedLsqOptions ridge;
  ridge.regularization = Eigen::MatrixXd::Identity(4, 4);
  ridge.lambda = 0.25;
  const Eigen::MatrixXd y = constrained_least_squares(Eigen::MatrixXd::Identity(4, 4), data, Eigen::MatrixXd(0, 4),
                                                      Eigen::MatrixXd(0, 1), ridge);
  EXPECT_LT((y - data / 1.25).cwiseAbs().maxCoeff(), 1e-14);
}

// Random well-posed problems with weights, a semidefinite regulariser and three right-hand sides
// agree with the KKT solution; the constraints hold to rounding.
TEST(ConstrainedLsq, AgreesWithKkt) {
  for (unsigned seed = 0; seed < 20; ++seed) {
    const int n = 12, k = 30, m = 4, r = 3;
    const Eigen::MatrixXd A = random_matrix(k, n, seed), B = random_matrix(k, r, seed + 100);
    const Eigen::MatrixXd C = random_matrix(m, n, seed + 200), D = random_matrix(m, r, seed + 300);
    const Eigen::MatrixXd G = random_matrix(5, n, seed + 400);  // R = G^T G has rank 5
    ConstrainedLsqOptions o;
    o.weights = random_matrix(k, 1, seed + 500).array().abs() + 0.1;
    o.regularization = G.transpose() * G;
    o.lambda = 0.3;
    const Eigen::MatrixXd x = constrained_least_squares(A, B, C, D, o);
    const Eigen::MatrixXd ref = kkt_solution(A, B, C, D, o.weights, o.regularization, o.lambda);
    EXPECT_LT((x - ref).cwiseAbs().maxCoeff(), 1e-11) << "seed " << seed;
    EXPECT_LT((C * x - D).cwiseAbs().maxCoeff(), 1e-13) << "seed " << seed;
  }
}

// A is rank-deficient (columns 0 and 1 identical, so A sees only x0 + x1), but the constraint
// x0 - x1 = 2 makes the problem well posed: x0 + x1 = mean of b, hence x0 = (mean + 2)/2.
TEST(ConstrainedLsq, RankDeficientDataWellPosedWithConstraints) {
  Eigen::MatrixXd A(3, 2);
  A << 1, 1, 1, 1, 1, 1;
  const Eigen::Vector3d b(1.0, 2.0, 6.0);
  Eigen::MatrixXd C(1, 2);
  C << 1, -1;
  const Eigen::MatrixXd x = constrained_least_squares(A, b, C, Eigen::MatrixXd::Constant(1, 1, 2.0));
  EXPECT_NEAR(x(0, 0), (3.0 + 2.0) / 2, 1e-14);
  EXPECT_NEAR(x(1, 0), (3.0 - 2.0) / 2, 1e-14);
}

// Redundant but consistent constraints (a row repeated, a row that is the sum of two others) are
// accepted and the solution equals the one with the independent rows only.
TEST(ConstrainedLsq, RedundantConsistentConstraints) {
  const Eigen::MatrixXd A = random_matrix(10, 6, 7), b = random_matrix(10, 1, 8);
  const Eigen::MatrixXd C0 = random_matrix(2, 6, 9), d0 = random_matrix(2, 1, 10);
  Eigen::MatrixXd C(4, 6), d(4, 1);
  C << C0, C0.row(0), C0.row(0) + C0.row(1);
  d << d0, d0.row(0), d0.row(0) + d0.row(1);
  const Eigen::MatrixXd x = constrained_least_squares(A, b, C, d);
  const Eigen::MatrixXd ref = constrained_least_squares(A, b, C0, d0);
  EXPECT_LT((x - ref).cwiseAbs().maxCoeff(), 1e-12);
}

// (C.5)-(C.6): rows(A) + rows(C) == n with an invertible stacked matrix: the data are interpolated.
TEST(ConstrainedLsq, InterpolationCase) {
  const int n = 8;
  const Eigen::MatrixXd A = random_matrix(5, n, 11), B = random_matrix(5, 2, 12);
  const Eigen::MatrixXd C = random_matrix(3, n, 13), D = random_matrix(3, 2, 14);
  const Eigen::MatrixXd x = constrained_least_squares(A, B, C, D);
  Eigen::MatrixXd N(n, n), G(n, 2);
  N << A, C;
  G << B, D;
  const Eigen::MatrixXd ref = Eigen::FullPivLU<Eigen::MatrixXd>(N).solve(G);  // (C.6)
  EXPECT_LT((x - ref).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((A * x - B).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT((C * x - D).cwiseAbs().maxCoeff(), 1e-13);
}

// Constraints alone fix every unknown: the data rows do not matter.
TEST(ConstrainedLsq, FullyConstrained) {
  const Eigen::MatrixXd C = random_matrix(4, 4, 15), D = random_matrix(4, 1, 16);
  const Eigen::MatrixXd x = constrained_least_squares(Eigen::MatrixXd(0, 4), Eigen::MatrixXd(0, 1), C, D);
  EXPECT_LT((C * x - D).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(ConstrainedLsq, InconsistentConstraintsAreInputErrors) {
  Eigen::MatrixXd C(2, 3);
  C << 1, 1, 0, 2, 2, 0;  // x0 + x1 = 1 and 2 (x0 + x1) = 3 contradict
  const Eigen::MatrixXd d = (Eigen::MatrixXd(2, 1) << 1.0, 3.0).finished();
  try {
    constrained_least_squares(Eigen::MatrixXd::Identity(3, 3), Eigen::MatrixXd::Ones(3, 1), C, d);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("inconsistent"), std::string::npos) << e.what();
  }
}

TEST(ConstrainedLsq, UnderdeterminedIsNumericalErrorWithRank) {
  // 5 unknowns, 2 data rows, 1 constraint: 4 free directions but only rank 2 of data on them.
  try {
    constrained_least_squares(random_matrix(2, 5, 17), random_matrix(2, 1, 18), random_matrix(1, 5, 19),
                              random_matrix(1, 1, 20));
    FAIL() << "expected NumericalError";
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("rank only 2"), std::string::npos) << what;
    EXPECT_NE(what.find("leave 4 free"), std::string::npos) << what;
  }
}

TEST(ConstrainedLsq, ShapeAndOptionErrors) {
  const Eigen::MatrixXd A = Eigen::MatrixXd::Identity(3, 3), b = Eigen::MatrixXd::Ones(3, 1);
  EXPECT_THROW(constrained_least_squares(A, Eigen::MatrixXd::Ones(2, 1), Eigen::MatrixXd(0, 3), Eigen::MatrixXd(0, 1)),
               InputError);
  EXPECT_THROW(constrained_least_squares(A, b, Eigen::MatrixXd::Ones(1, 2), Eigen::MatrixXd::Ones(1, 1)), InputError);
  ConstrainedLsqOptions negative;
  negative.weights = Eigen::Vector3d(1, -1, 1);
  EXPECT_THROW(constrained_least_squares(A, b, Eigen::MatrixXd(0, 3), Eigen::MatrixXd(0, 1), negative), InputError);
  ConstrainedLsqOptions indefinite;
  indefinite.regularization = Eigen::Vector3d(1, -1, 1).asDiagonal();
  indefinite.lambda = 1.0;
  EXPECT_THROW(constrained_least_squares(A, b, Eigen::MatrixXd(0, 3), Eigen::MatrixXd(0, 1), indefinite), InputError);
}

}  // namespace
}  // namespace polarform
