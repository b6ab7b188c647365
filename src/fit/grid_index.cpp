// Uniform grid index over 2D or 3D points: building (two-pass counting sort) and the radius and
// ring (k-nearest) queries.
#include "src/fit/grid_index.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "src/error.h"

namespace polarform {

namespace {

template <int Dim>
std::array<int, Dim> cell_counts(const Eigen::Matrix<double, Dim, 1>& extent, double size) {
  std::array<int, Dim> c{};
  for (int d = 0; d < Dim; ++d)  // spec B3: max(1, ⌈L/size⌉), not ⌊L/size⌋
    c[d] = std::max(1, static_cast<int>(std::ceil(extent[d] / size)));
  return c;
}

template <int Dim>
double total(const std::array<int, Dim>& c) {
  double t = 1.0;
  for (int v : c) t *= v;
  return t;
}

}  // namespace

// Piegl & Tiller 2001, §3.2 (cell size α·sqrt(area/n)); Kantz 2003, §4.3.
template <int Dim>
GridIndex<Dim>::GridIndex(const Points& points, double cell_size, double alpha) : points_(&points) {
  const Eigen::Index n = points.cols();
  if (!points.allFinite()) throw InputError("grid index: a point has a non-finite coordinate");
  Point extent = Point::Zero();
  if (n > 0) {
    low_ = points.rowwise().minCoeff();
    extent = points.rowwise().maxCoeff() - low_;
  }
  if (cell_size > 0.0) {
    size_ = cell_size;
  } else {
    double measure = 1.0;
    int k = 0;
    for (int d = 0; d < Dim; ++d)
      if (extent[d] > 0.0) {
        measure *= extent[d];
        ++k;
      }
    size_ = k == 0 ? 1.0 : alpha * std::pow(measure / static_cast<double>(n), 1.0 / k);
  }
  cells_ = cell_counts<Dim>(extent, size_);
  while (total<Dim>(cells_) > 4.0 * static_cast<double>(n) + 64.0) {
    size_ *= 1.25;
    cells_ = cell_counts<Dim>(extent, size_);
  }
  // Two passes: count, then place (compressed rows, no per-cell vectors).
  std::vector<int> cell(static_cast<std::size_t>(n));
  start_.assign(static_cast<std::size_t>(total<Dim>(cells_)) + 1, 0);
  for (Eigen::Index i = 0; i < n; ++i) {
    cell[i] = linear(cell_of(points.col(i)));
    ++start_[cell[i] + 1];
  }
  for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
  index_.resize(static_cast<std::size_t>(n));
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (Eigen::Index i = 0; i < n; ++i) index_[fill[cell[i]]++] = static_cast<int>(i);
}

template <int Dim>
std::array<int, Dim> GridIndex<Dim>::cell_of(const Point& p) const {
  std::array<int, Dim> c{};
  for (int d = 0; d < Dim; ++d) {
    const double f = std::floor((p[d] - low_[d]) / size_);
    c[d] = f < 0.0 ? 0 : (f >= cells_[d] - 1 ? cells_[d] - 1 : static_cast<int>(f));
  }
  return c;
}

template <int Dim>
int GridIndex<Dim>::linear(const std::array<int, Dim>& c) const {
  int l = c[0];
  for (int d = 1; d < Dim; ++d) l = l * cells_[d] + c[d];
  return l;
}

// Kantz 2003, §4.3: the cells the ball around q overlaps, each point tested.
template <int Dim>
void GridIndex<Dim>::radius(const Point& q, double r, std::vector<int>& out) const {
  out.clear();
  if (index_.empty() || !(r >= 0.0)) return;
  const std::array<int, Dim> lo = cell_of(q - Point::Constant(r));
  const std::array<int, Dim> hi = cell_of(q + Point::Constant(r));
  const double r2 = r * r;
  std::array<int, Dim> c = lo;
  for (;;) {
    const auto [b, e] = cell_points(linear(c));
    for (const int* it = b; it != e; ++it)
      if ((points_->col(*it) - q).squaredNorm() <= r2) out.push_back(*it);
    int d = Dim - 1;
    while (d >= 0 && ++c[d] > hi[d]) c[d] = lo[d], --d;
    if (d < 0) break;
  }
  std::sort(out.begin(), out.end());
}

// Piegl & Tiller's ring search: ring L holds the cells at Chebyshev cell distance L from q's cell;
// every point outside rings 0..L is at least (wall distance of q in its cell) + L·size away.
template <int Dim>
void GridIndex<Dim>::nearest(const Point& q, int k, std::vector<int>& out, int* rings) const {
  out.clear();
  if (rings) *rings = 0;
  if (index_.empty() || k <= 0) return;
  using Entry = std::pair<double, int>;  // (squared distance, index): ties by index
  std::priority_queue<Entry> best;       // the k best so far, worst on top
  const std::array<int, Dim> c0 = cell_of(q);
  double wall = std::numeric_limits<double>::infinity();
  int last_ring = 0;
  for (int d = 0; d < Dim; ++d) {
    const double lo = low_[d] + c0[d] * size_;
    wall = std::min({wall, std::max(0.0, q[d] - lo), std::max(0.0, lo + size_ - q[d])});
    last_ring = std::max({last_ring, c0[d], cells_[d] - 1 - c0[d]});
  }
  for (int ring = 0; ring <= last_ring; ++ring) {
    std::array<int, Dim> lo{}, hi{};
    for (int d = 0; d < Dim; ++d) {
      lo[d] = std::max(0, c0[d] - ring);
      hi[d] = std::min(cells_[d] - 1, c0[d] + ring);
    }
    std::array<int, Dim> c = lo;
    for (;;) {
      int cheb = 0;
      for (int d = 0; d < Dim; ++d) cheb = std::max(cheb, std::abs(c[d] - c0[d]));
      if (cheb == ring) {
        const auto [b, e] = cell_points(linear(c));
        for (const int* it = b; it != e; ++it) {
          const Entry entry{(points_->col(*it) - q).squaredNorm(), *it};
          if (static_cast<int>(best.size()) < k) {
            best.push(entry);
          } else if (entry < best.top()) {
            best.pop();
            best.push(entry);
          }
        }
      }
      int d = Dim - 1;
      while (d >= 0 && ++c[d] > hi[d]) c[d] = lo[d], --d;
      if (d < 0) break;
    }
    if (rings) *rings = ring;
    const double bound = wall + ring * size_;
    if (static_cast<int>(best.size()) == k && best.top().first < bound * bound) break;
  }
  out.resize(best.size());
  for (auto it = out.rbegin(); it != out.rend(); ++it) {
    *it = best.top().second;
    best.pop();
  }
}

template <int Dim>
int GridIndex<Dim>::nearest(const Point& q, int* rings) const {
  std::vector<int> out;
  nearest(q, 1, out, rings);
  return out.empty() ? -1 : out[0];
}

template class GridIndex<2>;
template class GridIndex<3>;

}  // namespace polarform
