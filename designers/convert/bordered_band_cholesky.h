// Cholesky factorisation A = L·Lᵀ of a symmetric positive definite matrix that is banded apart
// from a border: entries only within `bandwidth` of the diagonal, except in the last `border`
// rows and columns, which may be full. A periodic spline's normal equations take this form when
// the last p control values are the border (their basis functions wrap to the first spans). The
// band costs O(N·w²), the border O(m·N·w + m²·N) (Golub & Van Loan 2013, §4.3.5 band Cholesky,
// with the border eliminated last).
#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

namespace polarform {

class BorderedBandCholesky {
 public:
  // size: the order of A; bandwidth: w, the band's half width; border: m, 0 <= m <= size.
  BorderedBandCholesky(int size, int bandwidth, int border);

  // A(i, j) += value (and A(j, i): one call for the pair); (i, j) must lie within the band or the
  // border.
  void add(int i, int j, double value) {
    if (i < j) std::swap(i, j);
    if (i >= n_)
      border(i - n_, j) += value;
    else if (i - j <= w_)
      band(i, j) += value;
    else
      outside_band();
  }
  // Factorises A in place; false when A is not (numerically) positive definite.
  bool factorize();
  // x with A·x = b, after factorize().
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  [[noreturn]] static void outside_band();
  double& band(int i, int k) { return band_[static_cast<std::size_t>(i) * (w_ + 1) + (i - k)]; }
  double band(int i, int k) const {
    return band_[static_cast<std::size_t>(i) * (w_ + 1) + (i - k)];
  }
  double& border(int r, int k) { return border_[static_cast<std::size_t>(r) * size_ + k]; }
  double border(int r, int k) const { return border_[static_cast<std::size_t>(r) * size_ + k]; }

  int size_, w_, m_, n_;        // n_ = size − m: the banded part's order
  std::vector<double> band_;    // row i: A(i, i − w .. i) of the banded part, then L
  std::vector<double> border_;  // row r: A(n_ + r, 0 .. size − 1), then L
  std::vector<double> inverse_diagonal_;  // 1 / L(i, i), after factorize()
};

}  // namespace polarform
