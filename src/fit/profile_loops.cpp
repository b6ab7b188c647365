#include "src/fit/profile_loops.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <sstream>

#include "src/error.h"
#include "src/fit/circle_fit.h"
#include "src/number_text.h"

namespace polarform {

namespace {

constexpr double kLinkPerSpacing = 16.0;  // link radius / p90 nearest-neighbour distance
constexpr double kMaxLoopGap = std::numbers::pi / 2;  // largest angular gap of a loop
constexpr double kMinRingness = 0.25;                 // p5 / median distance from the loop's centre

// Points hashed into square cells of side c: sorted cell keys, the points they hold, and the
// runs of one key (the occupied cells).
class CellIndex {
 public:
  CellIndex(const Eigen::Matrix2Xd& p, double c) : p_(p) {
    lo_ = p.rowwise().minCoeff();
    const double extent = (p.rowwise().maxCoeff() - lo_).maxCoeff();
    c_ = std::max({c, extent / double(1 << 30), 1e-300});
    order_.resize(static_cast<std::size_t>(p.cols()));
    std::iota(order_.begin(), order_.end(), 0);
    std::vector<std::int64_t> key(order_.size());
    for (Eigen::Index k = 0; k < p.cols(); ++k)
      key[static_cast<std::size_t>(k)] = cell_key(p.col(k));
    std::sort(order_.begin(), order_.end(), [&](int a, int b) {
      return key[static_cast<std::size_t>(a)] < key[static_cast<std::size_t>(b)];
    });
    keys_.resize(order_.size());
    for (std::size_t i = 0; i < order_.size(); ++i)
      keys_[i] = key[static_cast<std::size_t>(order_[i])];
    for (std::size_t i = 0; i < keys_.size(); ++i)
      if (i == 0 || keys_[i] != keys_[i - 1]) runs_.push_back(static_cast<int>(i));
    runs_.push_back(static_cast<int>(keys_.size()));
  }

  std::size_t occupied() const { return runs_.size() - 1; }
  // The points of occupied cell r.
  const int* begin(std::size_t r) const { return order_.data() + runs_[r]; }
  const int* end(std::size_t r) const { return order_.data() + runs_[r + 1]; }

  // Calls f(r) for every occupied cell r within `reach` cells of cell r0 (r0 itself included).
  template <class F>
  void cells_near(std::size_t r0, int reach, F f) const {
    const auto [ix, iy] = unpack(keys_[static_cast<std::size_t>(runs_[r0])]);
    for (std::int64_t dx = -reach; dx <= reach; ++dx)
      for (std::int64_t dy = -reach; dy <= reach; ++dy) {
        const auto it = std::lower_bound(keys_.begin(), keys_.end(), pack(ix + dx, iy + dy));
        if (it != keys_.end() && *it == pack(ix + dx, iy + dy))
          f(static_cast<std::size_t>(
              std::upper_bound(runs_.begin(), runs_.end(), static_cast<int>(it - keys_.begin())) -
              runs_.begin() - 1));
      }
  }

 private:
  static constexpr std::int64_t kShift = std::int64_t(1) << 32;
  std::pair<std::int64_t, std::int64_t> cell(const Eigen::Vector2d& q) const {
    return {static_cast<std::int64_t>(std::floor((q.x() - lo_.x()) / c_)),
            static_cast<std::int64_t>(std::floor((q.y() - lo_.y()) / c_))};
  }
  static std::int64_t pack(std::int64_t ix, std::int64_t iy) { return ix * kShift + iy; }
  static std::pair<std::int64_t, std::int64_t> unpack(std::int64_t key) {  // of a point's cell:
    return {key / kShift, key % kShift};                                   // both indices >= 0
  }
  std::int64_t cell_key(const Eigen::Vector2d& q) const {
    const auto [ix, iy] = cell(q);
    return pack(ix, iy);
  }

  const Eigen::Matrix2Xd& p_;
  Eigen::Vector2d lo_;
  double c_ = 1.0;
  std::vector<int> order_, runs_;
  std::vector<std::int64_t> keys_;
};

// The 90th percentile of the points' nearest-neighbour distances, on cells holding a few points
// each (the cell side shrunk from the box's until they do; a point alone in its 3 x 3 cells counts
// as one side away).
double spacing(const Eigen::Matrix2Xd& p) {
  const double n = static_cast<double>(p.cols());
  double c = (p.rowwise().maxCoeff() - p.rowwise().minCoeff()).maxCoeff() / std::sqrt(n);
  for (int round = 0; round < 8; ++round) {
    const double occupancy = n / static_cast<double>(CellIndex(p, c).occupied());
    if (occupancy <= 8.0) break;
    c *= std::max(0.1, 4.0 / occupancy);
  }
  const CellIndex index(p, c);
  std::vector<double> nearest(static_cast<std::size_t>(p.cols()), c);
  for (std::size_t r = 0; r < index.occupied(); ++r)
    index.cells_near(r, 1, [&](std::size_t q) {
      for (const int* a = index.begin(r); a != index.end(r); ++a)
        for (const int* b = index.begin(q); b != index.end(q); ++b)
          if (*a != *b)
            nearest[static_cast<std::size_t>(*a)] =
                std::min(nearest[static_cast<std::size_t>(*a)], (p.col(*a) - p.col(*b)).norm());
    });
  const std::size_t q = static_cast<std::size_t>(0.9 * static_cast<double>(nearest.size() - 1));
  std::nth_element(nearest.begin(), nearest.begin() + static_cast<std::ptrdiff_t>(q),
                   nearest.end());
  return nearest[q];
}

int find(std::vector<int>& parent, int a) {
  while (parent[static_cast<std::size_t>(a)] != a)
    a = parent[static_cast<std::size_t>(a)] =
        parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
  return a;
}

// The largest circular gap between the directions of the points seen from c.
double largest_gap(const Eigen::Matrix2Xd& p, const Eigen::Vector2d& c) {
  std::vector<double> a(static_cast<std::size_t>(p.cols()));
  for (Eigen::Index k = 0; k < p.cols(); ++k)
    a[static_cast<std::size_t>(k)] = std::atan2(p(1, k) - c.y(), p(0, k) - c.x());
  std::sort(a.begin(), a.end());
  double gap = a.front() + 2 * std::numbers::pi - a.back();
  for (std::size_t i = 1; i < a.size(); ++i) gap = std::max(gap, a[i] - a[i - 1]);
  return gap;
}

double quantile(std::vector<double> v, double q) {
  const std::size_t i = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(i), v.end());
  return v[i];
}

ProfileContour contour(const Eigen::Matrix2Xd& p) {
  ProfileContour c;
  c.points = static_cast<std::size_t>(p.cols());
  if (largest_gap(p, Eigen::Vector2d::Zero()) <= kMaxLoopGap) {
    c.loop = c.around_centre = true;
  } else {
    try {
      c.centre = fit_circle(p).centre;
    } catch (const InputError&) {
      return c;  // collinear: an open piece
    }
  }
  std::vector<double> d(c.points);
  for (Eigen::Index k = 0; k < p.cols(); ++k)
    d[static_cast<std::size_t>(k)] = (p.col(k) - c.centre).norm();
  c.radius = quantile(d, 0.5);
  if (!c.around_centre)
    c.loop =
        largest_gap(p, c.centre) <= kMaxLoopGap && quantile(d, 0.05) >= kMinRingness * c.radius;
  return c;
}

// Decimals that give x three significant digits ("about" a radius).
int about_decimals(double x) {
  return std::clamp(2 - static_cast<int>(std::floor(std::log10(std::max(std::abs(x), 1e-12)))), 0,
                    12);
}

std::string count_word(std::size_t n) {
  static const char* words[] = {"no",  "one",   "two",   "three", "four", "five",
                                "six", "seven", "eight", "nine",  "ten"};
  return n <= 10 ? words[n] : std::to_string(n);
}

}  // namespace

std::vector<ProfileContour> profile_contours(const Eigen::Matrix2Xd& p) {
  const Eigen::Index n = p.cols();
  if (n < 24) return {};
  const double link = kLinkPerSpacing * spacing(p);
  // Cells of side link/√2: the points of one cell are linked; a cell and one within two cells
  // are linked by their first pair within the link distance.
  const CellIndex index(p, link / std::sqrt(2.0));
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  const auto join = [&](int a, int b) {
    parent[static_cast<std::size_t>(find(parent, a))] = find(parent, b);
  };
  for (std::size_t r = 0; r < index.occupied(); ++r)
    for (const int* a = index.begin(r) + 1; a < index.end(r); ++a) join(*a, *index.begin(r));
  for (std::size_t r = 0; r < index.occupied(); ++r)
    index.cells_near(r, 2, [&](std::size_t q) {
      if (q <= r || find(parent, *index.begin(q)) == find(parent, *index.begin(r))) return;
      for (const int* a = index.begin(r); a != index.end(r); ++a)
        for (const int* b = index.begin(q); b != index.end(q); ++b)
          if ((p.col(*a) - p.col(*b)).norm() <= link) return join(*a, *b);
    });
  std::vector<std::vector<Eigen::Index>> members(static_cast<std::size_t>(n));
  for (Eigen::Index k = 0; k < n; ++k)
    members[static_cast<std::size_t>(find(parent, static_cast<int>(k)))].push_back(k);
  const std::size_t least =
      std::max<std::size_t>(12, static_cast<std::size_t>(0.01 * static_cast<double>(n)));
  std::vector<ProfileContour> out;
  for (const std::vector<Eigen::Index>& m : members) {
    if (m.size() < least) continue;
    Eigen::Matrix2Xd q(2, static_cast<Eigen::Index>(m.size()));
    for (std::size_t a = 0; a < m.size(); ++a) q.col(static_cast<Eigen::Index>(a)) = p.col(m[a]);
    out.push_back(contour(q));
  }
  std::stable_sort(out.begin(), out.end(), [](const ProfileContour& a, const ProfileContour& b) {
    return a.points > b.points;
  });
  return out;
}

std::string describe_loops(const std::vector<ProfileContour>& contours,
                           const Eigen::Vector2d& offset) {
  std::vector<ProfileContour> loops;
  for (const ProfileContour& c : contours)
    if (c.loop) loops.push_back(c);
  if (loops.size() < 2) return "";
  std::sort(loops.begin(), loops.end(), [](const ProfileContour& a, const ProfileContour& b) {
    return a.around_centre != b.around_centre ? a.around_centre : a.radius > b.radius;
  });
  const auto about = [](double radius) { return format_trimmed(radius, about_decimals(radius)); };
  std::ostringstream o;
  o << count_word(loops.size()) << " loops found (";
  const bool all_around = std::all_of(loops.begin(), loops.end(),
                                      [](const ProfileContour& c) { return c.around_centre; });
  if (all_around) {
    o << "radii about ";
    for (std::size_t i = 0; i < loops.size(); ++i)
      o << (i == 0                  ? ""
            : i + 1 == loops.size() ? " and "
                                    : ", ")
        << about(loops[i].radius) << " mm";
    o << " around the centre";
  } else {
    for (std::size_t i = 0; i < loops.size(); ++i) {
      const ProfileContour& c = loops[i];
      o << (i == 0 ? "" : ", ") << "radius about " << about(c.radius) << " mm ";
      if (c.around_centre) {
        o << "around the centre";
      } else {  // the centre as closely as the radius
        const Eigen::Vector2d at = c.centre + offset;
        const int d = about_decimals(c.radius);
        o << "around (" << format_trimmed(at.x(), d) << ", " << format_trimmed(at.y(), d) << ")";
      }
    }
  }
  o << "): use scan-cam, or remove the inner loop" << (loops.size() > 2 ? "s" : "");
  return o.str();
}

}  // namespace polarform
