// Points grouped into cells of about 32 over comparably scaled coordinates (s alone for curves,
// s and t for surfaces), and a value's residuals about its local (weighted) least-squares quadratic
// in a cell. The single-valuedness check and the outlier search look at the data cell by cell
// through these: small enough for a quadratic to follow a smooth r = F, large enough to judge
// noise.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <vector>

namespace polarform {

class CellGrid {
 public:
  // A uniform grid over the bounding box of s (and t, when not empty; then of equal length) with
  // about n / points_per_cell cells, shaped to the box's aspect ratio.
  CellGrid(const Eigen::VectorXd& s, const Eigen::VectorXd& t, int points_per_cell = 32);

  bool surface() const { return surface_; }
  int ns() const { return ns_; }
  int nt() const { return nt_; }
  int cells() const { return ns_ * nt_; }
  double hs() const { return hs_; }
  double ht() const { return ht_; }
  // Cell c = i·nt + j covers [s0 + i·hs, s0 + (i+1)·hs) x [t0 + j·ht, …).
  double s_start(int i) const { return s0_ + i * hs_; }
  double t_start(int j) const { return t0_ + j * ht_; }
  double s_centre(int c) const { return s0_ + (c / nt_ + 0.5) * hs_; }
  double t_centre(int c) const { return t0_ + (c % nt_ + 0.5) * ht_; }
  // The cell (i, j) holding coordinates (s, t) (t ignored for curves), clamped to the grid.
  int cell_i(double s) const;
  int cell_j(double t) const;
  // The points of cell c: indices into s, t, in increasing order.
  int size(int c) const {
    return start_[static_cast<std::size_t>(c) + 1] - start_[static_cast<std::size_t>(c)];
  }
  const int* points(int c) const { return index_.data() + start_[static_cast<std::size_t>(c)]; }
  // Where cell c's points start in the cell-ordered arrays (index order of points()).
  int offset(int c) const { return start_[static_cast<std::size_t>(c)]; }

 private:
  bool surface_ = false;
  int ns_ = 1, nt_ = 1;
  double s0_ = 0, t0_ = 0, hs_ = 1, ht_ = 1;
  std::vector<int> start_, index_;  // counting sort: cell c holds index_[start_[c], start_[c+1])
};

// Residuals of value about its least-squares quadratic in the cell's normalised coordinates
// ((s − sc)/hs, and (t − tc)/ht for surfaces: Terms = 3 for curves, 6 for surfaces), written to
// res[0, m) for the points idx[0, m); weights w[0, m) when given, else 1. A tiny ridge keeps
// degenerate cells (collinear points) solvable.
template <int Terms>
void cell_quadratic_residuals(const int* idx, int m, const Eigen::VectorXd& s,
                              const Eigen::VectorXd& t, const Eigen::VectorXd& value, double sc,
                              double tc, double hs, double ht, double* res,
                              const double* w = nullptr) {
  using Vec = Eigen::Matrix<double, Terms, 1>;
  using Mat = Eigen::Matrix<double, Terms, Terms>;
  auto row = [&](int a) {
    Vec x;
    const double x1 = (s[idx[a]] - sc) / hs;
    if constexpr (Terms == 3) {
      x << 1.0, x1, x1 * x1;
    } else {
      const double x2 = (t[idx[a]] - tc) / ht;
      x << 1.0, x1, x1 * x1, x2, x2 * x2, x1 * x2;
    }
    return x;
  };
  Mat A = Mat::Zero();
  Vec b = Vec::Zero();
  for (int a = 0; a < m; ++a) {
    const Vec x = row(a);
    if (w) {
      A.noalias() += w[a] * x * x.transpose();
      b += w[a] * x * value[idx[a]];
    } else {
      A.noalias() += x * x.transpose();
      b += x * value[idx[a]];
    }
  }
  A.diagonal().array() += 1e-12 * A.trace();
  const Vec c = A.ldlt().solve(b);
  for (int a = 0; a < m; ++a) res[a] = value[idx[a]] - row(a).dot(c);
}

}  // namespace polarform
