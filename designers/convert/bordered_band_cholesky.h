// Cholesky factorisation A = L·Lᵀ of a symmetric positive definite matrix of 2 × 2 blocks that is
// banded apart from a border: blocks only within `bandwidth` blocks of the diagonal, except in the
// last `border` block rows and columns, which may be full. A plane spline's normal equations in
// its control values (x_j, y_j) take this form, a periodic spline's last p control values the
// border (their basis functions wrap to the first spans). The band costs O(N·w²), the border
// O(m·N·w + m²·N) (Golub & Van Loan 2013, §4.3.5 band Cholesky, row by row, with the border
// eliminated last), here by blocks: each entry takes the scalar algorithm's operations in its
// order, so that the factor is the scalar one to the last bit, at a fraction of the index work.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace polarform {

class BorderedBandCholesky {
 public:
  // blocks: N, the order of A in 2 × 2 blocks; bandwidth: w, the band's half width in blocks;
  // border: m, 0 <= m <= N.
  BorderedBandCholesky(int blocks, int bandwidth, int border);

  // Block (I, J) of A's lower triangle, I >= J, within the band or the border (InputError
  // otherwise); zero until set. Of a diagonal block only the lower triangle counts.
  Eigen::Matrix2d& lower(int I, int J) {
    if (!(J >= 0 && J <= I && I < size_) || (I < n_ && I - J > w_)) outside_band();
    return I >= n_ ? border(I - n_, J) : band(I, J);
  }
  // Factorises A in place; false when A is not (numerically) positive definite.
  bool factorize();
  // x with A·x = b (2N entries), after factorize().
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  // Block row I < n_: A(I, I − w .. I), stored backwards from the diagonal, then L.
  Eigen::Matrix2d& band(int I, int J) {
    return band_[static_cast<std::size_t>(I) * (w_ + 1) + (I - J)];
  }
  const Eigen::Matrix2d& band(int I, int J) const {
    return band_[static_cast<std::size_t>(I) * (w_ + 1) + (I - J)];
  }
  // Border block row R (A's block row n_ + R): A(n_ + R, 0 .. N − 1), then L.
  Eigen::Matrix2d& border(int R, int J) { return border_[static_cast<std::size_t>(R) * size_ + J]; }
  const Eigen::Matrix2d& border(int R, int J) const {
    return border_[static_cast<std::size_t>(R) * size_ + J];
  }
  [[noreturn]] static void outside_band();
  // S −= X·Yᵀ, entry by entry in the scalar order (X's first column, then its second).
  static void subtract(Eigen::Matrix2d& S, const Eigen::Matrix2d& X, const Eigen::Matrix2d& Y);
  // S ← S·L(J, J)⁻ᵀ by forward substitution: an off-diagonal block of L from what is left of A's.
  void divide(Eigen::Matrix2d& S, const Eigen::Matrix2d& diagonal, int J) const;
  // S ← the Cholesky factor of the diagonal block S (its lower triangle); false unless positive.
  bool root(Eigen::Matrix2d& S, int I);

  int size_, w_, m_, n_;  // n_ = size − m: the banded part's order, in blocks
  std::vector<Eigen::Matrix2d> band_, border_;
  std::vector<double> inverse_diagonal_;  // 1 / L(i, i) of the 2N scalar rows, after factorize()
};

}  // namespace polarform
