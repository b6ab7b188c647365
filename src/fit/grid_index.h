// Uniform grid index over 2D or 3D points (Piegl & Tiller 2001, §3.2–3.3; Kantz 2003, §4.3): cubic
// cells of one size, points binned in compressed rows (counts, offsets, indices: two passes),
// radius search over the cells a ball overlaps and k-nearest search by rings of cells. O(n) to
// build and exact. The seeds' cell count ⌊L/size⌋ overflows at the far wall; here it is max(1,
// ⌈L/size⌉) and the cell index is clamped (spec B3, "index formula fix").
#pragma once

#include <Eigen/Core>
#include <array>
#include <utility>
#include <vector>

namespace polarform {

template <int Dim>
class GridIndex {
 public:
  static_assert(Dim == 2 || Dim == 3, "GridIndex is 2D or 3D");
  using Point = Eigen::Matrix<double, Dim, 1>;
  using Points = Eigen::Matrix<double, Dim, Eigen::Dynamic>;

  // Bins the columns of `points` (kept by reference: they must outlive the index). cell_size <= 0
  // picks α·(box measure / n)^(1/k) over the k axes of non-zero extent (P&T §3.2 with α = 1),
  // enlarged when needed so that there are at most 4n + 64 cells. Throws InputError on
  // non-finite coordinates.
  explicit GridIndex(const Points& points, double cell_size = 0.0, double alpha = 1.0);

  double cell_size() const { return size_; }
  const std::array<int, Dim>& cells() const { return cells_; }
  int cell_count() const { return static_cast<int>(start_.size()) - 1; }
  const Points& points() const { return *points_; }

  // The cell (per axis) holding p: ⌊(p − low)/size⌋ clamped to [0, cells − 1].
  std::array<int, Dim> cell_of(const Point& p) const;
  // The points of the cell with linear (row-major) index c, in increasing index order.
  std::pair<const int*, const int*> cell_points(int c) const {
    return {index_.data() + start_[c], index_.data() + start_[c + 1]};
  }

  // Indices of all points with |p_i − q| <= r, in increasing order, written to out (cleared).
  void radius(const Point& q, double r, std::vector<int>& out) const;
  // The k points nearest to q (fewer when there are fewer points), nearest first; ties broken by
  // the smaller index. P&T's ring search: stop when the k-th distance is below the wall distance
  // of the rings not yet searched. rings (optional) receives the last ring searched (0: q's cell).
  void nearest(const Point& q, int k, std::vector<int>& out, int* rings = nullptr) const;
  // The index of the point nearest to q (-1 for an empty index).
  int nearest(const Point& q, int* rings = nullptr) const;

 private:
  int linear(const std::array<int, Dim>& c) const;

  const Points* points_;
  Point low_ = Point::Zero();
  double size_ = 1.0;
  std::array<int, Dim> cells_{};
  std::vector<int> start_, index_;  // cell c holds index_[start_[c], start_[c+1])
};

using GridIndex2d = GridIndex<2>;
using GridIndex3d = GridIndex<3>;

}  // namespace polarform
