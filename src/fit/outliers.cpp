#include "src/fit/outliers.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include "src/fit/cell_grid.h"
#include "src/fit/parallel.h"
#include "src/number_text.h"

namespace polarform {

namespace {

constexpr double kMadToSigma = 1.4826;  // σ of a normal distribution per median absolute deviation
constexpr double kTukey = 4.685;        // biweight cut-off in σ (95 % efficiency at the normal)
constexpr int kMinTrend1 = 8, kMinTrend2 = 12;  // points for a quadratic: curves, surfaces
constexpr int kNeighbours = 4;       // an outlier's nearest points looked at for a structure
constexpr std::size_t kFeature = 3;  // outliers lined up in this many make a feature

double median(std::vector<double>& a) {
  std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(a.size() / 2), a.end());
  return a[a.size() / 2];
}

// Residuals of r about its robust quadratic over the points idx[0, m) (normalised about sc, tc):
// plain least squares, then iteratively reweighted least squares with Tukey's biweight (Holland
// & Welsch 1977; Rousseeuw & Leroy 1987, §1.2) at the scale the plain residuals give (at least
// floor / kOutlierSigmas), held fixed: re-estimated each round, it would shrink onto a few points
// wherever a quadratic does not quite follow the shape. Where no plain residual exceeds half of
// kOutlierSigmas σ nothing is reweighted. The point at `left_out` (if >= 0) has no weight: its
// residual is its deviation from the others' trend. Returns the others' σ.
template <int Terms>
double robust_residuals(const int* idx, int m, const Eigen::VectorXd& s, const Eigen::VectorXd& t,
                        const Eigen::VectorXd& r, double sc, double tc, double hs, double ht,
                        double floor, double* res, int left_out = -1) {
  std::vector<double> a, w(static_cast<std::size_t>(m), 1.0);
  if (left_out >= 0) w[static_cast<std::size_t>(left_out)] = 0.0;
  const auto scale = [&] {
    a.clear();
    for (int k = 0; k < m; ++k)
      if (k != left_out) a.push_back(std::abs(res[k]));
    return kMadToSigma * median(a);
  };
  cell_quadratic_residuals<Terms>(idx, m, s, t, r, sc, tc, hs, ht, res, w.data());
  const double plain = scale();
  double largest = 0.0;
  for (int k = 0; k < m; ++k) largest = std::max(largest, k == left_out ? 0.0 : std::abs(res[k]));
  if (largest <= 0.5 * kOutlierSigmas * plain) return plain;  // nothing pulls the plain fit
  const double c = kTukey * std::max(plain, floor / kOutlierSigmas);
  for (int round = 0; c > 0.0 && round < 30; ++round) {
    double change = 0.0, total = 0.0;
    for (int k = 0; k < m; ++k) {
      if (k == left_out) continue;
      const double u = res[k] / c, nw = std::abs(u) < 1.0 ? (1 - u * u) * (1 - u * u) : 0.0;
      change = std::max(change, std::abs(nw - w[static_cast<std::size_t>(k)]));
      w[static_cast<std::size_t>(k)] = nw;
      total += nw;
    }
    if (change < 1e-6 || total < Terms) break;  // converged, or too few points keep weight
    cell_quadratic_residuals<Terms>(idx, m, s, t, r, sc, tc, hs, ht, res, w.data());
  }
  return scale();
}

// Point k's deviation from the robust quadratic of its neighbours, centred on it, and their σ:
// the neighbours within one cell width (in cell units), or two, three, four where fewer than
// 2 x kMinTrend are (near a spherical pole the cells in φ and θ hold few points); {0, -1} if even
// then too few. Centred, the quadratic misses the shape only by its fourth-order terms: the
// corners of a cell, where exact data deviates from the cell's quadratic by its third-order terms,
// are no outliers.
std::pair<double, double> centred_deviation(Eigen::Index k, const CellGrid& g,
                                            const Eigen::VectorXd& s, const Eigen::VectorXd& t,
                                            const Eigen::VectorXd& r, double floor) {
  const bool surface = g.surface();
  const int need = 2 * (surface ? kMinTrend2 : kMinTrend1);
  const int ci = g.cell_i(s[k]), cj = surface ? g.cell_j(t[k]) : 0;
  std::vector<int> idx;
  for (int reach = 1; reach <= 4; ++reach) {
    idx.assign(1, static_cast<int>(k));
    for (int i = std::max(0, ci - reach); i <= std::min(g.ns() - 1, ci + reach); ++i)
      for (int j = std::max(0, cj - reach); j <= std::min(g.nt() - 1, cj + reach); ++j) {
        const int c = i * g.nt() + j;
        for (int q = 0; q < g.size(c); ++q) {
          const int p = g.points(c)[q];
          const double ds = (s[p] - s[k]) / g.hs(), dt = surface ? (t[p] - t[k]) / g.ht() : 0.0;
          if (p != k && ds * ds + dt * dt <= reach * reach) idx.push_back(p);
        }
      }
    if (static_cast<int>(idx.size()) > need) break;
  }
  const int m = static_cast<int>(idx.size());
  if (m <= need) return {0.0, -1.0};
  std::vector<double> res(static_cast<std::size_t>(m));
  const double tk = surface ? t[k] : 0.0;
  const double sigma = surface ? robust_residuals<6>(idx.data(), m, s, t, r, s[k], tk, g.hs(),
                                                     g.ht(), floor, res.data(), 0)
                               : robust_residuals<3>(idx.data(), m, s, t, r, s[k], tk, g.hs(),
                                                     g.ht(), floor, res.data(), 0);
  return {res[0], sigma};
}

int find(std::vector<int>& parent, int a) {
  while (parent[static_cast<std::size_t>(a)] != a)
    a = parent[static_cast<std::size_t>(a)] =
        parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(a)])];
  return a;
}

// The candidates that line up with others (kFeature or more, linked where one is among the
// other's kNeighbours nearest points, in cell units, with a deviation of the same sign within half
// of the larger): a narrow feature or a short branch, dropped from the outliers.
std::vector<Eigen::Index> isolated(const std::vector<Eigen::Index>& candidates, const CellGrid& g,
                                   const Eigen::VectorXd& s, const Eigen::VectorXd& t,
                                   const Eigen::VectorXd& dev) {
  const int n = static_cast<int>(candidates.size());
  std::vector<int> slot(static_cast<std::size_t>(s.size()), -1);
  for (int a = 0; a < n; ++a)
    slot[static_cast<std::size_t>(candidates[static_cast<std::size_t>(a)])] = a;
  std::vector<int> parent(static_cast<std::size_t>(n));
  std::iota(parent.begin(), parent.end(), 0);
  auto at = [&](Eigen::Index k) {
    return Eigen::Vector2d(s[k] / g.hs(), g.surface() ? t[k] / g.ht() : 0.0);
  };
  for (int a = 0; a < n; ++a) {
    const Eigen::Index k = candidates[static_cast<std::size_t>(a)];
    const Eigen::Vector2d pk = at(k);
    const int ci = g.cell_i(s[k]), cj = g.surface() ? g.cell_j(t[k]) : 0;
    std::array<std::pair<double, int>, kNeighbours> nearest;
    nearest.fill({std::numeric_limits<double>::infinity(), -1});
    for (int i = std::max(0, ci - 1); i <= std::min(g.ns() - 1, ci + 1); ++i)
      for (int j = std::max(0, cj - 1); j <= std::min(g.nt() - 1, cj + 1); ++j) {
        const int c = i * g.nt() + j;
        for (int q = 0; q < g.size(c); ++q) {
          const int p = g.points(c)[q];
          if (p == k) continue;
          const double d = (at(p) - pk).squaredNorm();
          if (d < nearest.back().first) {
            nearest.back() = {d, p};
            std::sort(nearest.begin(), nearest.end());
          }
        }
      }
    for (const auto& [d, p] : nearest) {
      if (p < 0 || slot[static_cast<std::size_t>(p)] < 0) continue;
      const double a0 = dev[k], a1 = dev[p];
      if (a0 * a1 > 0 && std::abs(a0 - a1) <= 0.5 * std::max(std::abs(a0), std::abs(a1)))
        parent[static_cast<std::size_t>(find(parent, a))] =
            find(parent, slot[static_cast<std::size_t>(p)]);
    }
  }
  std::vector<std::size_t> size(static_cast<std::size_t>(n), 0);
  for (int a = 0; a < n; ++a) ++size[static_cast<std::size_t>(find(parent, a))];
  std::vector<Eigen::Index> out;
  for (int a = 0; a < n; ++a)
    if (size[static_cast<std::size_t>(find(parent, a))] < kFeature)
      out.push_back(candidates[static_cast<std::size_t>(a)]);
  return out;
}

}  // namespace

OutlierScan find_outliers(const Eigen::VectorXd& s, const Eigen::VectorXd& t,
                          const Eigen::VectorXd& r, double floor, int threads) {
  const std::size_t n = static_cast<std::size_t>(r.size());
  OutlierScan out;
  out.deviation = Eigen::VectorXd::Zero(r.size());
  if (n == 0) return out;
  const CellGrid g(s, t);
  const bool surface = g.surface();
  const int cells = g.cells(), min_trend = surface ? kMinTrend2 : kMinTrend1;
  std::vector<double> res(n, 0.0);                                   // in cell order
  std::vector<double> sigma(static_cast<std::size_t>(cells), -1.0);  // -1: not judged
  parallel_chunks(
      static_cast<std::size_t>(cells), worker_count(threads, static_cast<std::size_t>(cells), 256),
      [&](std::size_t b, std::size_t e, int) {
        std::vector<double> a;
        for (int c = static_cast<int>(b); c < static_cast<int>(e); ++c) {
          const int m = g.size(c);
          const int* idx = g.points(c);
          double* rc = res.data() + g.offset(c);
          double& sc = sigma[static_cast<std::size_t>(c)];
          if (m >= min_trend) {
            sc = surface ? robust_residuals<6>(idx, m, s, t, r, g.s_centre(c), g.t_centre(c),
                                               g.hs(), g.ht(), floor, rc)
                         : robust_residuals<3>(idx, m, s, t, r, g.s_centre(c), g.t_centre(c),
                                               g.hs(), g.ht(), floor, rc);
          } else if (m >= 3) {  // too few points for a trend: the cell's median
            a.resize(static_cast<std::size_t>(m));
            for (int k = 0; k < m; ++k) a[static_cast<std::size_t>(k)] = r[idx[k]];
            const double level = median(a);
            for (int k = 0; k < m; ++k)
              a[static_cast<std::size_t>(k)] = std::abs(rc[k] = r[idx[k]] - level);
            sc = kMadToSigma * median(a);
          }
        }
      });
  std::vector<double> judged;
  judged.reserve(n);
  for (int c = 0; c < cells; ++c)
    for (int k = 0; k < g.size(c); ++k) {
      const double d = res[static_cast<std::size_t>(g.offset(c) + k)];
      out.deviation[g.points(c)[k]] = d;
      if (sigma[static_cast<std::size_t>(c)] >= 0.0) judged.push_back(std::abs(d));
    }
  if (judged.empty()) return out;
  out.scale = kMadToSigma * median(judged);
  out.threshold = std::max(kOutlierSigmas * out.scale, floor);
  // Outliers lie beyond kOutlierSigmas of the larger of the data's σ and the local one, and
  // beyond the floor: first from their cell's trend, then (confirmed) from their neighbours' trend
  // centred on them.
  const auto beyond = [&](double deviation, double local) {
    return std::abs(deviation) > std::max(kOutlierSigmas * std::max(local, out.scale), floor);
  };
  std::vector<Eigen::Index> candidates;
  for (int c = 0; c < cells; ++c) {
    const double local = sigma[static_cast<std::size_t>(c)];
    for (int k = 0; local >= 0.0 && k < g.size(c); ++k)
      if (beyond(res[static_cast<std::size_t>(g.offset(c) + k)], local))
        candidates.push_back(g.points(c)[k]);
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<Eigen::Index> confirmed;
  for (Eigen::Index k : candidates) {
    const auto [deviation, local] = centred_deviation(k, g, s, t, r, floor);
    if (local < 0.0) {
      confirmed.push_back(k);  // too few neighbours to say more than the cell did
    } else if (beyond(deviation, local)) {
      out.deviation[k] = deviation;
      confirmed.push_back(k);
    }
  }
  out.points = isolated(confirmed, g, s, t, out.deviation);
  return out;
}

double outlier_floor(const Eigen::VectorXd& r) {
  if (r.size() == 0) return 0.0;
  std::vector<double> a(static_cast<std::size_t>(r.size()));
  for (Eigen::Index k = 0; k < r.size(); ++k) a[static_cast<std::size_t>(k)] = std::abs(r[k]);
  return 1e-4 * median(a);
}

OutlierReport settle_outliers(OutlierPolicy policy, const Eigen::VectorXd& s,
                              const Eigen::VectorXd& t, const Eigen::VectorXd& r,
                              const SingleValuedness& check, bool checked, const std::string& fit,
                              const PointPlace& place, const std::function<InputError()>& folds,
                              int threads) {
  OutlierReport report;
  report.policy = policy;
  const bool failed = checked && !check.single_valued;
  if (policy == OutlierPolicy::keep) {
    if (failed) throw folds();
    return report;
  }
  const OutlierScan scan = find_outliers(s, t, r, outlier_floor(r), threads);
  const std::size_t n = static_cast<std::size_t>(r.size());
  const bool few = !scan.points.empty() && static_cast<double>(scan.points.size()) <=
                                               kMaxOutlierFraction * static_cast<double>(n);
  if (failed) {  // explained by a few outliers, if without them the data is single-valued
    if (!few) throw folds();
    std::vector<char> out(n, 0);
    for (Eigen::Index k : scan.points) out[static_cast<std::size_t>(k)] = 1;
    const Eigen::Index rest = static_cast<Eigen::Index>(n - scan.points.size());
    Eigen::VectorXd rs(rest), rt(t.size() ? rest : 0), rr(rest);
    for (Eigen::Index k = 0, a = 0; k < r.size(); ++k) {
      if (out[static_cast<std::size_t>(k)]) continue;
      rs[a] = s[k], rr[a] = r[k];
      if (t.size()) rt[a] = t[k];
      ++a;
    }
    if (!check_single_valued(rs, rt, rr, threads).single_valued) throw folds();
  }
  report.scale = scan.scale;
  report.threshold = scan.threshold;
  if (policy == OutlierPolicy::refuse && !few) return report;
  report.points = scan.points;
  report.count = scan.points.size();
  for (Eigen::Index k : scan.points)
    if (std::abs(scan.deviation[k]) >= report.largest)
      report.largest = std::abs(scan.deviation[k]), report.largest_point = k;
  if (policy == OutlierPolicy::refuse) {
    std::ostringstream o;
    o << fit << ": " << report.count << (report.count == 1 ? " outlier" : " outliers") << " of "
      << n << " points at > " << number_text(kOutlierSigmas)
      << " σ (σ = " << number_text(report.scale) << " mm, threshold "
      << number_text(report.threshold) << " mm; largest " << number_text(report.largest)
      << " mm at " << place(report.largest_point) << "): rerun with --reject-outliers";
    throw InputError(o.str());
  }
  return report;
}

}  // namespace polarform
