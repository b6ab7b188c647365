#include "designers/convert/bordered_band_cholesky.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "src/error.h"

namespace polarform {

BorderedBandCholesky::BorderedBandCholesky(int size, int bandwidth, int border)
    : size_(size), w_(bandwidth), m_(border), n_(size - border) {
  if (size < 0 || bandwidth < 0 || border < 0 || border > size)
    throw InputError("bordered band Cholesky: bad shape");
  band_.assign(static_cast<std::size_t>(n_) * (w_ + 1), 0.0);
  border_.assign(static_cast<std::size_t>(m_) * size_, 0.0);
}

void BorderedBandCholesky::outside_band() {
  throw InputError("bordered band Cholesky: entry outside the band");
}

// Golub & Van Loan Alg. 4.3.5 (band Cholesky, row by row), then the border rows against the band
// and against each other.
bool BorderedBandCholesky::factorize() {
  inverse_diagonal_.assign(static_cast<std::size_t>(size_), 0.0);
  // L(i, k) = L[row(i) − k] (band() stores row i backwards from its diagonal).
  double* L = band_.data();
  const auto row = [&](int i) { return static_cast<std::ptrdiff_t>(i) * (w_ + 2); };
  for (int i = 0; i < n_; ++i) {
    const std::ptrdiff_t ri = row(i);
    for (int j = std::max(0, i - w_); j <= i; ++j) {
      const std::ptrdiff_t rj = row(j);
      double s = L[ri - j];
      for (int k = std::max(0, i - w_); k < j; ++k) s -= L[ri - k] * L[rj - k];
      if (j < i) {
        L[ri - j] = s * inverse_diagonal_[j];
      } else {
        if (!(s > 0)) return false;
        L[ri - i] = std::sqrt(s);
        inverse_diagonal_[i] = 1 / L[ri - i];
      }
    }
  }
  for (int r = 0; r < m_; ++r) {
    double* Br = &border(r, 0);
    for (int j = 0; j < n_; ++j) {
      const std::ptrdiff_t rj = row(j);
      double s = Br[j];
      for (int k = std::max(0, j - w_); k < j; ++k) s -= Br[k] * L[rj - k];
      Br[j] = s * inverse_diagonal_[j];
    }
    for (int c = 0; c <= r; ++c) {
      const double* Bc = &border(c, 0);
      double s = Br[n_ + c];
      for (int k = 0; k < n_ + c; ++k) s -= Br[k] * Bc[k];
      if (c < r) {
        Br[n_ + c] = s * inverse_diagonal_[n_ + c];
      } else {
        if (!(s > 0)) return false;
        Br[n_ + r] = std::sqrt(s);
        inverse_diagonal_[n_ + r] = 1 / Br[n_ + r];
      }
    }
  }
  return true;
}

Eigen::VectorXd BorderedBandCholesky::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = b;
  // L·y = b.
  for (int i = 0; i < n_; ++i) {
    double s = x(i);
    for (int k = std::max(0, i - w_); k < i; ++k) s -= band(i, k) * x(k);
    x(i) = s * inverse_diagonal_[i];
  }
  for (int r = 0; r < m_; ++r) {
    double s = x(n_ + r);
    for (int k = 0; k < n_ + r; ++k) s -= border(r, k) * x(k);
    x(n_ + r) = s * inverse_diagonal_[n_ + r];
  }
  // Lᵀ·x = y: the border's unknowns first.
  for (int r = m_ - 1; r >= 0; --r) {
    double s = x(n_ + r);
    for (int c = r + 1; c < m_; ++c) s -= border(c, n_ + r) * x(n_ + c);
    x(n_ + r) = s * inverse_diagonal_[n_ + r];
  }
  for (int i = n_ - 1; i >= 0; --i) {
    double s = x(i);
    for (int k = i + 1; k <= std::min(n_ - 1, i + w_); ++k) s -= band(k, i) * x(k);
    for (int r = 0; r < m_; ++r) s -= border(r, i) * x(n_ + r);
    x(i) = s * inverse_diagonal_[i];
  }
  return x;
}

}  // namespace polarform
