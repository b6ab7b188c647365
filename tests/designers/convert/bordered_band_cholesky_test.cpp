// BorderedBandCholesky against Eigen's dense LLT on random symmetric positive definite matrices
// of 2 × 2 blocks that are banded apart from a border (the shape of a periodic plane spline's
// normal equations).
#include "designers/convert/bordered_band_cholesky.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <random>

#include "src/error.h"

namespace polarform {
namespace {

// A random SPD matrix of N × N blocks with half-bandwidth w blocks whose last m block rows and
// columns are full: B·Bᵀ of a random matrix with the same pattern is denser, so the pattern's
// entries are filled directly and the diagonal made dominant.
Eigen::MatrixXd bordered_band_matrix(int blocks, int w, int m, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int size = 2 * blocks;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(size, size);
  for (int i = 0; i < size; ++i)
    for (int j = 0; j <= i; ++j)
      if (i / 2 - j / 2 <= w || i / 2 >= blocks - m) A(i, j) = A(j, i) = u(rng);
  for (int i = 0; i < size; ++i) A(i, i) = A.row(i).cwiseAbs().sum() + 1.0;
  return A;
}

// A's lower blocks into L.
void fill(BorderedBandCholesky& L, const Eigen::MatrixXd& A) {
  for (int I = 0; I < A.rows() / 2; ++I)
    for (int J = 0; J <= I; ++J)
      if (!A.block<2, 2>(2 * I, 2 * J).isZero()) L.lower(I, J) = A.block<2, 2>(2 * I, 2 * J);
}

TEST(BorderedBandCholesky, SolvesLikeDenseCholesky) {
  std::mt19937 rng(7);
  for (const auto& [blocks, w, m] :
       {std::tuple{1, 0, 0}, {6, 1, 0}, {6, 1, 2}, {20, 5, 5}, {5, 5, 5}, {11, 5, 5}, {3, 1, 3}}) {
    SCOPED_TRACE(testing::Message() << blocks << " " << w << " " << m);
    const Eigen::MatrixXd A = bordered_band_matrix(blocks, w, m, rng);
    BorderedBandCholesky L(blocks, w, m);
    fill(L, A);
    ASSERT_TRUE(L.factorize());
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(2 * blocks, -2.0, 3.0);
    const Eigen::VectorXd x = L.solve(b), expected = A.llt().solve(b);
    EXPECT_LT((x - expected).norm(), 1e-12 * expected.norm());
    EXPECT_LT((A * x - b).norm(), 1e-12 * b.norm());
  }
}

// The factor is the scalar band Cholesky's (Golub & Van Loan Alg. 4.3.5 on the 2N × 2N matrix,
// each entry A(i, j) − Σ_k L(i, k)·L(j, k) over increasing k) to the last bit.
TEST(BorderedBandCholesky, SolvesAsTheScalarAlgorithmToTheLastBit) {
  std::mt19937 rng(11);
  const Eigen::MatrixXd A = bordered_band_matrix(9, 3, 3, rng);
  const int size = static_cast<int>(A.rows());
  Eigen::MatrixXd S = A;  // the scalar algorithm on the dense lower triangle, zeros included
  Eigen::VectorXd inverse(size);
  for (int i = 0; i < size; ++i)
    for (int j = 0; j <= i; ++j) {
      double s = S(i, j);
      for (int k = 0; k < j; ++k) s -= S(i, k) * S(j, k);
      if (j < i) {
        S(i, j) = s * inverse(j);
      } else {
        S(i, i) = std::sqrt(s);
        inverse(i) = 1 / S(i, i);
      }
    }
  Eigen::VectorXd y = Eigen::VectorXd::LinSpaced(size, -2.0, 3.0);
  const Eigen::VectorXd b = y;
  for (int i = 0; i < size; ++i) {
    double s = y(i);
    for (int k = 0; k < i; ++k) s -= S(i, k) * y(k);
    y(i) = s * inverse(i);
  }
  for (int i = size - 1; i >= 0; --i) {
    double s = y(i);
    for (int k = i + 1; k < size; ++k) s -= S(k, i) * y(k);
    y(i) = s * inverse(i);
  }
  BorderedBandCholesky L(9, 3, 3);
  fill(L, A);
  ASSERT_TRUE(L.factorize());
  const Eigen::VectorXd x = L.solve(b);
  for (int i = 0; i < size; ++i) EXPECT_EQ(x(i), y(i)) << i;
}

TEST(BorderedBandCholesky, RejectsIndefiniteMatricesAndBlocksOutsideThePattern) {
  BorderedBandCholesky L(2, 1, 0);
  L.lower(0, 0) << 1.0, 0.0, 0.0, 1.0;
  L.lower(1, 1) << 1.0, 0.0, 0.0, 1.0;
  L.lower(1, 0) << 2.0, 0.0, 0.0, 0.0;  // A(2, 0) = 2: eigenvalues 3 and −1 on rows 0 and 2
  EXPECT_FALSE(L.factorize());
  BorderedBandCholesky narrow(5, 1, 1);
  EXPECT_THROW(narrow.lower(3, 0), InputError);
  EXPECT_THROW(narrow.lower(0, 1), InputError);  // upper triangle
  EXPECT_NO_THROW(narrow.lower(4, 0));           // the border row
}

}  // namespace
}  // namespace polarform
