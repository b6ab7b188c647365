#include "designers/convert/bordered_band_cholesky.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "src/error.h"

namespace polarform {

BorderedBandCholesky::BorderedBandCholesky(int blocks, int bandwidth, int border)
    : size_(blocks), w_(bandwidth), m_(border), n_(blocks - border) {
  if (blocks < 0 || bandwidth < 0 || border < 0 || border > blocks)
    throw InputError("bordered band Cholesky: bad shape");
  band_.assign(static_cast<std::size_t>(n_) * (w_ + 1), Eigen::Matrix2d::Zero());
  border_.assign(static_cast<std::size_t>(m_) * size_, Eigen::Matrix2d::Zero());
}

void BorderedBandCholesky::outside_band() {
  throw InputError("bordered band Cholesky: block outside the band");
}

void BorderedBandCholesky::subtract(Eigen::Matrix2d& S, const Eigen::Matrix2d& X,
                                    const Eigen::Matrix2d& Y) {
  for (int c = 0; c < 2; ++c) {
    S.col(c) -= X.col(0) * Y(c, 0);
    S.col(c) -= X.col(1) * Y(c, 1);
  }
}

void BorderedBandCholesky::divide(Eigen::Matrix2d& S, const Eigen::Matrix2d& diagonal,
                                  int J) const {
  S.col(0) *= inverse_diagonal_[2 * J];
  S.col(1) -= S.col(0) * diagonal(1, 0);
  S.col(1) *= inverse_diagonal_[2 * J + 1];
}

bool BorderedBandCholesky::root(Eigen::Matrix2d& S, int I) {
  if (!(S(0, 0) > 0)) return false;
  S(0, 0) = std::sqrt(S(0, 0));
  inverse_diagonal_[2 * I] = 1 / S(0, 0);
  S(1, 0) *= inverse_diagonal_[2 * I];
  S(1, 1) -= S(1, 0) * S(1, 0);
  if (!(S(1, 1) > 0)) return false;
  S(1, 1) = std::sqrt(S(1, 1));
  inverse_diagonal_[2 * I + 1] = 1 / S(1, 1);
  return true;
}

// Golub & Van Loan Alg. 4.3.5 (band Cholesky, row by row), then the border rows against the band
// and against each other; by blocks, each scalar entry A(i, j) − Σ_k L(i, k)·L(j, k) over k in
// increasing order (the zero terms left of the band skipped).
bool BorderedBandCholesky::factorize() {
  inverse_diagonal_.assign(2 * static_cast<std::size_t>(size_), 0.0);
  for (int I = 0; I < n_; ++I)
    for (int J = std::max(0, I - w_); J <= I; ++J) {
      Eigen::Matrix2d S = band(I, J);  // a local: no store through the loop's reads
      for (int K = std::max(0, I - w_); K < J; ++K) subtract(S, band(I, K), band(J, K));
      if (J < I)
        divide(S, band(J, J), J);
      else if (!root(S, I))
        return false;
      band(I, J) = S;
    }
  for (int R = 0; R < m_; ++R) {
    Eigen::Matrix2d* B = &border(R, 0);
    for (int J = 0; J < n_; ++J) {
      Eigen::Matrix2d S = B[J];
      for (int K = std::max(0, J - w_); K < J; ++K) subtract(S, B[K], band(J, K));
      divide(S, band(J, J), J);
      B[J] = S;
    }
    for (int C = 0; C <= R; ++C) {
      const Eigen::Matrix2d* Bc = &border(C, 0);
      Eigen::Matrix2d S = B[n_ + C];
      for (int K = 0; K < n_ + C; ++K) subtract(S, B[K], Bc[K]);
      if (C < R)
        divide(S, Bc[n_ + C], n_ + C);
      else if (!root(S, n_ + R))
        return false;
      B[n_ + C] = S;
    }
  }
  return true;
}

Eigen::VectorXd BorderedBandCholesky::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = b;
  // L·y = b, row by row: block row I's blocks from column `from` on (at(K) = L(I, K)).
  const auto forward = [&](int I, int from, const auto& at) {
    for (int r = 0; r < 2; ++r) {
      double s = x(2 * I + r);
      for (int K = from; K < I; ++K) {
        s -= at(K)(r, 0) * x(2 * K);
        s -= at(K)(r, 1) * x(2 * K + 1);
      }
      if (r == 1) s -= at(I)(1, 0) * x(2 * I);
      x(2 * I + r) = s * inverse_diagonal_[2 * I + r];
    }
  };
  for (int I = 0; I < n_; ++I)
    forward(I, std::max(0, I - w_), [&](int K) -> const Eigen::Matrix2d& { return band(I, K); });
  for (int R = 0; R < m_; ++R)
    forward(n_ + R, 0, [&](int K) -> const Eigen::Matrix2d& { return border(R, K); });
  // Lᵀ·x = y, row by row backwards: the border's unknowns first.
  for (int R = m_ - 1; R >= 0; --R)
    for (int r = 1; r >= 0; --r) {
      double s = x(2 * (n_ + R) + r);
      if (r == 0) s -= border(R, n_ + R)(1, 0) * x(2 * (n_ + R) + 1);
      for (int C = R + 1; C < m_; ++C)
        for (int c = 0; c < 2; ++c) s -= border(C, n_ + R)(c, r) * x(2 * (n_ + C) + c);
      x(2 * (n_ + R) + r) = s * inverse_diagonal_[2 * (n_ + R) + r];
    }
  for (int I = n_ - 1; I >= 0; --I)
    for (int r = 1; r >= 0; --r) {
      double s = x(2 * I + r);
      if (r == 0) s -= band(I, I)(1, 0) * x(2 * I + 1);
      for (int K = I + 1; K <= std::min(n_ - 1, I + w_); ++K)
        for (int c = 0; c < 2; ++c) s -= band(K, I)(c, r) * x(2 * K + c);
      for (int R = 0; R < m_; ++R)
        for (int c = 0; c < 2; ++c) s -= border(R, I)(c, r) * x(2 * (n_ + R) + c);
      x(2 * I + r) = s * inverse_diagonal_[2 * I + r];
    }
  return x;
}

}  // namespace polarform
