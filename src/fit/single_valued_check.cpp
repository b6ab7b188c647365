#include "src/fit/single_valued_check.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include "src/error.h"
#include "src/fit/cell_grid.h"

namespace polarform {

namespace {

// The points' deviations within their own branch: split the cell at the largest gap of the
// sorted residuals (enough points on both sides, as in branches()) and detrend each side by
// itself, so that two branches everywhere (a concentric bore) do not inflate the noise to their
// distance — nor, through a common trend that jumps with the branches' mix along s, to a
// fraction of it.
template <int Terms>
void within_branch_deviations(const int* idx, int m, const double* res, const Eigen::VectorXd& s,
                              const Eigen::VectorXd& t, const Eigen::VectorXd& r, double sc,
                              double tc, double hs, double ht, double* out) {
  const int need = std::max(3, m / 10);
  std::vector<int> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return res[a] < res[b]; });
  int cut = m - 1;  // last position (in order) of the lower side
  double best = -1.0;
  for (int a = need - 1; a + need < m; ++a)
    if (res[order[a + 1]] - res[order[a]] > best) best = res[order[a + 1]] - res[order[a]], cut = a;
  std::vector<int> side_idx;
  std::vector<double> side_res;
  const auto side = [&](int from, int to) {  // positions order[from, to]
    side_idx.clear();
    for (int a = from; a <= to; ++a) side_idx.push_back(idx[order[a]]);
    side_res.resize(side_idx.size());
    const int k = static_cast<int>(side_idx.size());
    if (k >= 2 * Terms) {
      cell_quadratic_residuals<Terms>(side_idx.data(), k, s, t, r, sc, tc, hs, ht, side_res.data());
    } else {
      const double median = res[order[(from + to) / 2]];
      for (int a = from; a <= to; ++a) side_res[a - from] = res[order[a]] - median;
    }
    for (int a = from; a <= to; ++a) out[order[a]] = std::abs(side_res[a - from]);
  };
  side(0, cut);
  if (cut + 1 < m) side(cut + 1, m - 1);
  // Keep the split only where the gap stands far out of the spread it leaves (two branches);
  // one cluster split at its largest gap would understate its own noise.
  std::vector<double> spread(out, out + m);
  std::nth_element(spread.begin(), spread.begin() + m / 2, spread.end());
  if (!(best > 8 * 1.4826 * spread[m / 2]))
    for (int a = 0; a < m; ++a) out[a] = std::abs(res[a]);
}

struct CellFold {
  bool fold = false;
  double separation = 0.0;
};

// Two branches: the largest gap in the sorted residuals (enough points on both sides) exceeds the
// threshold and the smaller group is interleaved with the larger one: along s for curves (a runs
// count), for surfaces at least 40% of its points have their nearest neighbour in the cell (in
// normalised s, t) in the other group. A steep or narrow single-valued feature also splits the
// residuals, but into groups that occupy separate parts of the cell.
CellFold branches(const int* idx, int m, const double* res, const Eigen::VectorXd& s,
                  const Eigen::VectorXd& t, const Eigen::VectorXd& r, bool surface, double hs,
                  double ht, double threshold) {
  const int need = std::max(3, m / 10);
  std::vector<int> order(m);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return res[a] < res[b]; });
  double best = 0.0;
  int cut = -1;
  for (int a = need - 1; a + need < m; ++a) {
    const double gap = res[order[a + 1]] - res[order[a]];
    if (gap > best) best = gap, cut = a;
  }
  CellFold f;
  if (cut < 0 || !(best > threshold)) return f;
  std::vector<char> upper(m, 0);
  for (int a = cut + 1; a < m; ++a) upper[order[a]] = 1;
  const char minority = cut + 1 > m - cut - 1 ? 1 : 0;
  auto pos = [&](int a) {
    const int k = idx[a];
    return Eigen::Vector2d(s[k] / hs, surface ? t[k] / ht : 0.0);
  };
  int members = 0, crossing = 0;
  for (int a = 0; surface && a < m; ++a) {
    if (upper[a] != minority) continue;
    ++members;
    double nearest = std::numeric_limits<double>::infinity();
    int other = 0;
    for (int b = 0; b < m; ++b) {
      if (b == a) continue;
      const double d = (pos(a) - pos(b)).squaredNorm();
      if (d < nearest) nearest = d, other = upper[b] != upper[a];
    }
    crossing += other;
  }
  if (surface) {
    f.fold = crossing >= 0.4 * members;
  } else {
    // Curves: count the changes of branch along s (Wald–Wolfowitz runs). Interleaved branches of
    // m1 and m2 points change about 2·m1·m2/m times; a steep single-valued feature at most twice.
    std::vector<int> by_s(m);
    std::iota(by_s.begin(), by_s.end(), 0);
    std::sort(by_s.begin(), by_s.end(), [&](int a, int b) { return s[idx[a]] < s[idx[b]]; });
    int changes = 0;
    for (int a = 1; a < m; ++a) changes += upper[by_s[a]] != upper[by_s[a - 1]];
    const double m1 = cut + 1, m2 = m - cut - 1;
    f.fold = changes >= std::max(4.0, m1 * m2 / m);
  }
  // The branches' distance: difference of their median radii.
  std::vector<double> lo, hi;
  for (int a = 0; a < m; ++a) (upper[a] ? hi : lo).push_back(r[idx[a]]);
  auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
  };
  f.separation = std::abs(median(hi) - median(lo));
  return f;
}

}  // namespace

SingleValuedness check_single_valued(const Eigen::VectorXd& s, const Eigen::VectorXd& t,
                                     const Eigen::VectorXd& r, int threads) {
  const bool surface = t.size() != 0;
  const std::size_t n = static_cast<std::size_t>(r.size());
  SingleValuedness out;
  if (n < 16) return out;
  const CellGrid g(s, t);
  const int cells = g.cells();
  const int min_points = surface ? 12 : 8;
  const auto from = [&](int c) { return static_cast<std::size_t>(g.offset(c)); };
  std::vector<double> res(n, 0.0);
  parallel_chunks(static_cast<std::size_t>(cells), worker_count(threads, static_cast<std::size_t>(cells), 256),
                  [&](std::size_t b, std::size_t e, int) {
    for (int c = static_cast<int>(b); c < static_cast<int>(e); ++c) {
      if (g.size(c) < min_points) continue;
      const double sc = g.s_centre(c), tc = g.t_centre(c);
      double* rs = res.data() + from(c);
      if (surface)
        cell_quadratic_residuals<6>(g.points(c), g.size(c), s, t, r, sc, tc, g.hs(), g.ht(), rs);
      else
        cell_quadratic_residuals<3>(g.points(c), g.size(c), s, t, r, sc, tc, g.hs(), g.ht(), rs);
    }
  });
  // Robust noise: 1.4826 · median deviation of the detrended points within their branch.
  std::vector<double> all;
  all.reserve(n);
  for (int c = 0; c < cells; ++c)
    if (g.size(c) >= min_points) {
      all.resize(all.size() + static_cast<std::size_t>(g.size(c)));
      const double sc = g.s_centre(c), tc = g.t_centre(c);
      double* dev = all.data() + all.size() - g.size(c);
      if (surface)
        within_branch_deviations<6>(g.points(c), g.size(c), res.data() + from(c), s, t, r, sc, tc,
                                    g.hs(), g.ht(), dev);
      else
        within_branch_deviations<3>(g.points(c), g.size(c), res.data() + from(c), s, t, r, sc, tc,
                                    g.hs(), g.ht(), dev);
    }
  if (all.empty()) return out;
  std::nth_element(all.begin(), all.begin() + all.size() / 2, all.end());
  out.noise = 1.4826 * all[all.size() / 2];
  std::vector<double> radii(r.data(), r.data() + r.size());
  std::nth_element(radii.begin(), radii.begin() + radii.size() / 2, radii.end());
  out.typical_radius = std::abs(radii[radii.size() / 2]);
  out.threshold = std::max(8.0 * out.noise, 1e-4 * out.typical_radius);

  std::vector<CellFold> fold(static_cast<std::size_t>(cells));
  for (int c = 0; c < cells; ++c)
    if (g.size(c) >= min_points)
      fold[static_cast<std::size_t>(c)] = branches(g.points(c), g.size(c), res.data() + from(c), s,
                                                   t, r, surface, g.hs(), g.ht(), out.threshold);
  // Connected fold cells (4-neighbours) become regions.
  std::vector<int> label(static_cast<std::size_t>(cells), -1);
  for (int c0 = 0; c0 < cells; ++c0) {
    if (!fold[static_cast<std::size_t>(c0)].fold || label[static_cast<std::size_t>(c0)] >= 0) continue;
    FoldRegion reg;
    reg.s0 = reg.t0 = std::numeric_limits<double>::infinity();
    reg.s1 = reg.t1 = -reg.s0;
    std::vector<int> stack = {c0};
    label[static_cast<std::size_t>(c0)] = static_cast<int>(out.folds.size());
    while (!stack.empty()) {
      const int c = stack.back();
      stack.pop_back();
      const int i = c / g.nt(), j = c % g.nt();
      reg.s0 = std::min(reg.s0, g.s_start(i)), reg.s1 = std::max(reg.s1, g.s_start(i + 1));
      reg.t0 = std::min(reg.t0, g.t_start(j)), reg.t1 = std::max(reg.t1, g.t_start(j + 1));
      reg.separation = std::max(reg.separation, fold[static_cast<std::size_t>(c)].separation);
      reg.points += static_cast<std::size_t>(g.size(c));
      const int nb[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
      for (const auto& q : nb) {
        if (q[0] < 0 || q[0] >= g.ns() || q[1] < 0 || q[1] >= g.nt()) continue;
        const int d = q[0] * g.nt() + q[1];
        if (fold[static_cast<std::size_t>(d)].fold && label[static_cast<std::size_t>(d)] < 0) {
          label[static_cast<std::size_t>(d)] = label[static_cast<std::size_t>(c0)];
          stack.push_back(d);
        }
      }
    }
    if (!surface) reg.t0 = reg.t1 = 0.0;
    out.folds.push_back(reg);
  }
  out.single_valued = out.folds.empty();
  return out;
}

void require_thin_data(const SingleValuedness& check, const std::string& fit) {
  if (check.noise <= kMaxRelativeScatter * check.typical_radius) return;
  std::ostringstream o;
  o.precision(4);
  o << fit << ": the points fill a region instead of lying on one curve or surface about the "
    << "centre: their radii scatter by σ = " << check.noise << " about any smooth r = F, "
    << 100 * check.noise / check.typical_radius << " % of the typical radius "
    << check.typical_radius << " (at most " << 100 * kMaxRelativeScatter << " %)";
  throw InputError(o.str());
}

std::string describe_folds(const SingleValuedness& check, const std::string& s_name, double s_unit,
                           const std::string& t_name, double t_unit) {
  std::ostringstream o;
  o.precision(4);
  const std::size_t listed = std::min(check.folds.size(), kListedFolds);
  for (std::size_t i = 0; i < listed; ++i) {
    const FoldRegion& f = check.folds[i];
    if (i > 0) o << ", ";
    o << s_name << " in [" << f.s0 * s_unit << ", " << f.s1 * s_unit << "]";
    if (!t_name.empty()) o << " x " << t_name << " in [" << f.t0 * t_unit << ", " << f.t1 * t_unit << "]";
    o << " (branches " << f.separation << " apart)";
  }
  if (check.folds.size() > listed) o << " … and " << check.folds.size() - listed << " more";
  return o.str();
}

}  // namespace polarform
