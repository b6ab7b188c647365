// BorderedBandCholesky against Eigen's dense LLT on random symmetric positive definite matrices
// that are banded apart from a border (the shape of a periodic spline's normal equations).
#include "designers/convert/bordered_band_cholesky.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <random>

#include "src/error.h"

namespace polarform {
namespace {

// A random SPD matrix with half-bandwidth w whose last m rows and columns are full: B·Bᵀ of a
// random matrix with the same pattern is denser, so the pattern's entries are filled directly and
// the diagonal made dominant.
Eigen::MatrixXd bordered_band_matrix(int size, int w, int m, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(size, size);
  for (int i = 0; i < size; ++i)
    for (int j = 0; j <= i; ++j)
      if (i - j <= w || i >= size - m) A(i, j) = A(j, i) = u(rng);
  for (int i = 0; i < size; ++i) A(i, i) = A.row(i).cwiseAbs().sum() + 1.0;
  return A;
}

TEST(BorderedBandCholesky, SolvesLikeDenseCholesky) {
  std::mt19937 rng(7);
  for (const auto& [size, w, m] : {std::tuple{1, 0, 0},
                                   {12, 3, 0},
                                   {12, 3, 4},
                                   {40, 11, 10},
                                   {10, 11, 10},
                                   {22, 11, 10},
                                   {6, 2, 6}}) {
    SCOPED_TRACE(testing::Message() << size << " " << w << " " << m);
    const Eigen::MatrixXd A = bordered_band_matrix(size, w, m, rng);
    BorderedBandCholesky L(size, w, m);
    for (int i = 0; i < size; ++i)
      for (int j = 0; j <= i; ++j)
        if (A(i, j) != 0.0) L.add(i, j, A(i, j));
    ASSERT_TRUE(L.factorize());
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(size, -2.0, 3.0);
    const Eigen::VectorXd x = L.solve(b), expected = A.llt().solve(b);
    EXPECT_LT((x - expected).norm(), 1e-12 * expected.norm());
    EXPECT_LT((A * x - b).norm(), 1e-12 * b.norm());
  }
}

TEST(BorderedBandCholesky, AddAccumulatesAndMirrors) {
  // A(0, 1) given in two parts, once as (0, 1) and once as (1, 0).
  BorderedBandCholesky L(2, 1, 0);
  L.add(0, 0, 4.0);
  L.add(1, 1, 3.0);
  L.add(0, 1, 0.5);
  L.add(1, 0, 0.5);
  ASSERT_TRUE(L.factorize());
  const Eigen::VectorXd x = L.solve(Eigen::Vector2d(5.0, 4.0));  // A = [4 1; 1 3]
  EXPECT_NEAR(x(0), 1.0, 1e-15);
  EXPECT_NEAR(x(1), 1.0, 1e-15);
}

TEST(BorderedBandCholesky, RejectsIndefiniteMatricesAndEntriesOutsideThePattern) {
  BorderedBandCholesky L(2, 1, 0);
  L.add(0, 0, 1.0);
  L.add(1, 1, 1.0);
  L.add(0, 1, 2.0);  // [1 2; 2 1]: eigenvalues 3 and −1
  EXPECT_FALSE(L.factorize());
  BorderedBandCholesky narrow(5, 1, 1);
  EXPECT_THROW(narrow.add(3, 0, 1.0), InputError);
  EXPECT_NO_THROW(narrow.add(4, 0, 1.0));  // the border row
}

}  // namespace
}  // namespace polarform
