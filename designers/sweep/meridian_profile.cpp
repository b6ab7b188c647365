// Profile curves of a meridian band: ring clusters or MLS-thinned scans, ordered, cornered and
// fitted (Kantz 2003, §4.5; spec K7).
#include "designers/sweep/meridian_profile.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <optional>
#include <string>
#include <utility>

#include "src/error.h"
#include "src/fit/corner_detection.h"
#include "src/fit/curve_distance.h"
#include "src/fit/curve_fit.h"
#include "src/fit/grid_index.h"
#include "src/fit/mls_thinning.h"
#include "src/fit/parallel.h"
#include "src/fit/point_ordering.h"
#include "src/fit/rotation_axis.h"
#include "src/nurbs/degree_elevation.h"

namespace polarform {

namespace {

// The shortest closed tour through the points: nearest neighbour from the lowest (z, r), which
// is an end of most profiles (so an open profile's tour returns along one long edge), then 2-opt
// (Croes 1958). Given two ends (the poles of a profile from axis to axis), the shortest path from
// the first to the second instead, closed by the edge back along the axis: the shortest closed
// tour may cut across a groove and leave part of the profile for a second run.
std::vector<int> shortest_tour(const Eigen::Matrix2Xd& P,
                               std::optional<std::pair<int, int>> ends = std::nullopt) {
  const int m = static_cast<int>(P.cols());
  int first = 0;
  for (int j = 1; j < m; ++j)
    if (P(0, j) < P(0, first) || (P(0, j) == P(0, first) && P(1, j) < P(1, first))) first = j;
  if (ends) first = ends->first;
  std::vector<int> tour{first};
  std::vector<char> used(static_cast<std::size_t>(m), 0);
  used[first] = 1;
  if (ends) used[ends->second] = 1;
  for (int s = ends ? 2 : 1; s < m; ++s) {
    int best = -1;
    double bd = 0.0;
    for (int j = 0; j < m; ++j)
      if (!used[j] && (best < 0 || (P.col(j) - P.col(tour.back())).norm() < bd))
        best = j, bd = (P.col(j) - P.col(tour.back())).norm();
    used[best] = 1;
    tour.push_back(best);
  }
  if (ends) tour.push_back(ends->second);
  auto d = [&](int a, int b) { return (P.col(tour[a]) - P.col(tour[b % m])).norm(); };
  // With ends the closing edge (m − 1 → 0) stays: j stops before it.
  const int last_j = ends ? m - 2 : m - 1;
  for (int pass = 0, improved = 1; improved && pass < 100 && m >= 4; ++pass) {
    improved = 0;
    for (int i = 0; i + 2 < m; ++i)
      for (int j = i + 2; j <= last_j; ++j) {
        if (i == 0 && j == m - 1) continue;
        if (d(i, i + 1) + d(j, j + 1) >
            d(i, j) + d(i + 1, j + 1) + 1e-12 * (d(i, i + 1) + d(j, j + 1))) {
          std::reverse(tour.begin() + i + 1, tour.begin() + j + 1);
          improved = 1;
        }
      }
  }
  return tour;
}

// Spec B1 on one ordered run of profile points, its corners and its ends on the axis.
MeridianLoop fit_loop(const Eigen::Matrix2Xd& pts, const Eigen::VectorXd& weights, bool closed,
                      double axis_snap, int support, const MeridianOptions& o, double tol) {
  MeridianLoop loop;
  loop.closed = closed;
  loop.points = pts;
  const int n = static_cast<int>(pts.cols());
  CurveFitOptions<2> f;
  f.degree = std::min(o.degree, closed ? o.degree : n - 1);
  f.closed = closed;
  f.weights = weights;
  f.tolerance = tol;
  f.corner_support = support;
  f.max_control_points = std::max(4 * n, 8);
  if (n >= 2 * support + 1 || closed)
    f.corners = detect_corners<2>(pts, closed, o.corner_angle, support);
  if (!closed) {
    f.fix_ends = true;
    if (o.axis_ends && pts(1, 0) <= axis_snap) f.start = Eigen::Vector2d(pts(0, 0), 0.0);
    if (o.axis_ends && pts(1, n - 1) <= axis_snap) f.end = Eigen::Vector2d(pts(0, n - 1), 0.0);
    loop.start_on_axis = f.start.has_value();
    loop.end_on_axis = f.end.has_value();
    if (loop.start_on_axis) loop.points(1, 0) = 0.0;
    if (loop.end_on_axis) loop.points(1, n - 1) = 0.0;
  }
  const CurveFit<2> fit = fit_curve<2>(loop.points, f);
  loop.curve = fit.curve;
  if (fit.curve.degree() < o.degree)  // a short run: the exact curve, degree raised
    loop.curve =
        NurbsCurve2d(elevate_degree(fit.curve.homogeneous(), o.degree - fit.curve.degree()));
  loop.fit_max = fit.max_distance;
  loop.tolerance_met = fit.tolerance_met;
  for (double c : fit.corner_parameters) loop.corners.push_back(loop.curve.point(c));
  return loop;
}

MeridianProfile ring_profile(const Eigen::Matrix2Xd& zr, const std::vector<int>& label, int m,
                             MeridianProfile out, const MeridianOptions& o, double merge) {
  Eigen::Matrix2Xd centre = Eigen::Matrix2Xd::Zero(2, m);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(m);
  for (Eigen::Index k = 0; k < zr.cols(); ++k)
    if (label[k] >= 0) centre.col(label[k]) += zr.col(k), count[label[k]] += 1;
  for (int c = 0; c < m; ++c) centre.col(c) /= count[c];
  const double on_axis = std::max(10 * merge, 1e-9 * out.size);
  std::vector<int> poles;
  for (int c = 0; c < m; ++c)
    if (centre(1, c) <= on_axis) poles.push_back(c);
  const std::vector<int> tour = poles.size() == 2 && m >= 4
                                    ? shortest_tour(centre, std::pair{poles[0], poles[1]})
                                    : shortest_tour(centre);
  // Cut the tour where it runs along the axis, and next to a pole that is not yet an end.
  std::vector<char> cut(static_cast<std::size_t>(m), 0);  // edge tour[i] → tour[i+1]
  auto axis_pt = [&](int i) { return centre(1, tour[(i + m) % m]) <= on_axis; };
  auto len = [&](int i) {
    return (centre.col(tour[i % m]) - centre.col(tour[(i + 1) % m])).norm();
  };
  for (int i = 0; i < m; ++i) cut[i] = axis_pt(i) && axis_pt(i + 1);
  for (int i = 0; i < m; ++i)
    if (axis_pt(i) && !cut[i] && !cut[(i - 1 + m) % m])
      cut[len(i) >= len(i + m - 1) ? i : (i - 1 + m) % m] = 1;
  // An open profile off the axis: the tour returns along one edge far longer than any other.
  if (std::find(cut.begin(), cut.end(), 1) == cut.end() && m >= 3) {
    std::vector<double> l(static_cast<std::size_t>(m));
    for (int i = 0; i < m; ++i) l[i] = len(i);
    const int longest = static_cast<int>(std::max_element(l.begin(), l.end()) - l.begin());
    std::vector<double> rest = l;
    rest.erase(rest.begin() + longest);
    if (l[longest] > 3 * *std::max_element(rest.begin(), rest.end())) cut[longest] = 1;
  }
  const auto first_cut = std::find(cut.begin(), cut.end(), 1);
  if (first_cut == cut.end()) {
    Eigen::Matrix2Xd pts(2, m);
    Eigen::VectorXd w(m);
    for (int i = 0; i < m; ++i) pts.col(i) = centre.col(tour[i]), w[i] = count[tour[i]];
    out.loops.push_back(fit_loop(pts, w, true, on_axis, 1, o, out.tolerance));
    return out;
  }
  const int start = static_cast<int>(first_cut - cut.begin()) + 1;
  std::vector<int> run;
  for (int s = 0; s < m; ++s) {
    const int i = (start + s) % m;
    run.push_back(tour[i]);
    if (cut[i]) {
      if (run.size() >= 2) {
        Eigen::Matrix2Xd pts(2, static_cast<Eigen::Index>(run.size()));
        Eigen::VectorXd w(pts.cols());
        for (std::size_t k = 0; k < run.size(); ++k)
          pts.col(k) = centre.col(run[k]), w[k] = count[run[k]];
        out.loops.push_back(fit_loop(pts, w, false, on_axis, 1, o, out.tolerance));
      }
      run.clear();
    }
  }
  return out;
}

// Spec B1 once more on every point of the band: each point takes the parameter of its foot on the
// nearest loop, and every loop is refitted to its points in that order, with its corners (the
// first point at or past each corner's parameter), its end points and its poles kept. The thinned
// nodes fix the order and the corners; the least squares over all points average the noise.
void refit_on_band(const Eigen::Matrix2Xd& band, MeridianProfile& out, const MeridianOptions& o) {
  std::deque<CurveDistance<2>> dist;
  for (const MeridianLoop& l : out.loops) dist.emplace_back(l.curve, l.closed);
  const Eigen::Index n = band.cols();
  std::vector<int> loop_of(static_cast<std::size_t>(n));
  std::vector<double> u_of(static_cast<std::size_t>(n));
  const int chunks = worker_count(o.threads, static_cast<std::size_t>(n));
  parallel_chunks(static_cast<std::size_t>(n), chunks, [&](std::size_t b, std::size_t e, int) {
    for (std::size_t k = b; k < e; ++k) {
      double best = INFINITY;
      for (std::size_t l = 0; l < dist.size(); ++l) {
        const auto f = dist[l].project(band.col(static_cast<Eigen::Index>(k)));
        if (f.distance < best) best = f.distance, loop_of[k] = static_cast<int>(l), u_of[k] = f.u;
      }
    }
  });
  for (std::size_t l = 0; l < out.loops.size(); ++l) {
    MeridianLoop& loop = out.loops[l];
    std::vector<int> ids;
    for (Eigen::Index k = 0; k < n; ++k)
      if (loop_of[k] == static_cast<int>(l)) ids.push_back(static_cast<int>(k));
    std::sort(ids.begin(), ids.end(), [&](int a, int b) { return u_of[a] < u_of[b]; });
    const int m = static_cast<int>(ids.size());
    if (m < 4 * (o.degree + 1) || m <= loop.points.cols()) continue;
    Eigen::Matrix2Xd pts(2, m);
    Eigen::VectorXd u(m);
    for (int k = 0; k < m; ++k) pts.col(k) = band.col(ids[k]), u[k] = u_of[ids[k]];
    CurveFitOptions<2> f;
    f.degree = o.degree;
    f.closed = loop.closed;
    f.tolerance = out.tolerance;
    f.parameters = (u.array() - loop.curve.front()) / (loop.curve.back() - loop.curve.front());
    f.max_control_points = std::max(static_cast<int>(loop.points.cols()), 8);
    f.corner_support = std::clamp(2 * m / static_cast<int>(loop.points.cols()), 8, 400);
    for (const Eigen::Vector2d& c : loop.corners) {
      const double uc = dist[l].project(c).u;
      f.corners.push_back(std::min<int>(
          m - 1, static_cast<int>(std::lower_bound(u.data(), u.data() + m, uc) - u.data())));
    }
    if (!loop.closed) {
      f.start = loop.curve.point(loop.curve.front());
      f.end = loop.curve.point(loop.curve.back());
    }
    const CurveFit<2> fit = fit_curve<2>(pts, f);
    loop.curve =
        fit.curve.degree() < o.degree
            ? NurbsCurve2d(elevate_degree(fit.curve.homogeneous(), o.degree - fit.curve.degree()))
            : fit.curve;
    loop.points = pts;
    loop.fit_max = fit.max_distance;
    loop.tolerance_met = fit.tolerance_met;
    loop.corners.clear();
    for (double c : fit.corner_parameters) loop.corners.push_back(loop.curve.point(c));
  }
}

// Kantz 2003, §4.4–4.5 on a scan band: an evenly strided subset of at most max_structure_points
// is made thin by MLS (the radius grows until the neighbourhood is linear, up to 400 neighbours,
// so that it outgrows the band's thickness), ordered into chains at the median radius the MLS
// used; the chains' kept nodes give each loop's order, corners and ends; then every point of the
// band (at most max_scan_points) refits it.
MeridianProfile scan_profile(const Eigen::Matrix2Xd& zr, MeridianProfile out,
                             const MeridianOptions& o) {
  auto subset = [&](int max_points) {
    const Eigen::Index stride =
        std::max<Eigen::Index>(1, (zr.cols() + max_points - 1) / max_points);
    Eigen::Matrix2Xd sub(2, (zr.cols() + stride - 1) / stride);
    for (Eigen::Index k = 0; k < sub.cols(); ++k) sub.col(k) = zr.col(k * stride);
    return sub;
  };
  const Eigen::Matrix2Xd sub = subset(o.max_structure_points);
  const GridIndex2d grid(sub);
  std::vector<double> nn;
  std::vector<int> two;
  const Eigen::Index step = std::max<Eigen::Index>(1, sub.cols() / 2000);
  for (Eigen::Index k = 0; k < sub.cols(); k += step) {
    grid.nearest(sub.col(k), 2, two);
    if (two.size() == 2) nn.push_back((sub.col(two[1]) - sub.col(k)).norm());
  }
  std::nth_element(nn.begin(), nn.begin() + nn.size() / 2, nn.end());
  out.spacing = std::max(nn.empty() ? 0.0 : nn[nn.size() / 2], 1e-9 * out.size);
  MlsOptions mo;
  mo.radius = 6 * out.spacing;
  mo.max_neighbours = 400;
  mo.growth_steps = 6;
  mo.threads = o.threads;
  const MlsThinning thinning = mls_thin(sub, mo);
  const Eigen::Matrix2Xd& thin = thinning.points;
  out.clusters = static_cast<int>(thin.cols());
  // The ordering radius bridges the gaps between neighbours along the thin band: at least the
  // median radius the MLS used and the median distance to the 24th nearest thinned point (about
  // 12 spacings along a curve, which random sampling leaves no gap as wide as).
  std::vector<double> used(thinning.radius.data(), thinning.radius.data() + thinning.radius.size());
  std::nth_element(used.begin(), used.begin() + used.size() / 2, used.end());
  const GridIndex2d thin_grid(thin);
  std::vector<double> reach;
  std::vector<int> near;
  for (Eigen::Index k = 0; k < thin.cols(); k += step) {
    thin_grid.nearest(thin.col(k), 25, near);
    if (!near.empty()) reach.push_back((thin.col(near.back()) - thin.col(k)).norm());
  }
  std::nth_element(reach.begin(), reach.begin() + reach.size() / 2, reach.end());
  const double order_radius =
      std::max({mo.radius, used[used.size() / 2], reach.empty() ? 0.0 : reach[reach.size() / 2]});
  const std::vector<OrderedChain> chains =
      order_points(thin, order_radius, std::max(20, static_cast<int>(thin.cols() / 100)));
  for (const OrderedChain& c : chains) {
    Eigen::Matrix2Xd pts(2, static_cast<Eigen::Index>(c.nodes.size()));
    for (std::size_t k = 0; k < c.nodes.size(); ++k) pts.col(k) = thin.col(c.nodes[k]);
    if (pts.cols() < 2) continue;
    out.loops.push_back(
        fit_loop(pts, Eigen::VectorXd(), c.closed, 2 * order_radius, 3, o, out.tolerance));
  }
  if (out.loops.empty())
    throw NumericalError("meridian profile: no profile could be ordered out of the points");
  refit_on_band(subset(o.max_scan_points), out, o);
  return out;
}

}  // namespace

// Kantz 2003, §4.5 (spec K7), with the ring-cluster path of spec K11 step 3.
MeridianProfile recover_meridian_profile(const Eigen::Matrix2Xd& zr, const MeridianOptions& o) {
  if (zr.cols() < 4)
    throw InputError("meridian profile: " + std::to_string(zr.cols()) + " points, need at least 4");
  if (!zr.allFinite()) throw InputError("meridian profile: a point has a non-finite coordinate");
  MeridianProfile out;
  out.size = (zr.rowwise().maxCoeff() - zr.rowwise().minCoeff()).norm();
  out.tolerance = o.tolerance > 0 ? o.tolerance : 1e-4 * out.size;
  const double merge =
      o.merge > 0 ? o.merge : std::max({1e-7 * out.size, 1e-2 * out.tolerance, 8 * o.rounding});
  std::vector<int> label;
  const int all = cluster_points(zr, merge, 1, label);
  std::vector<int> size(static_cast<std::size_t>(all), 0);
  for (int l : label) ++size[l];
  // Keep clusters of >= 3 points, and single points on the axis (a pole vertex).
  std::vector<int> keep(static_cast<std::size_t>(all), -1);
  int m = 0;
  Eigen::Index covered = 0;
  std::vector<double> rmin(static_cast<std::size_t>(all), INFINITY);
  for (Eigen::Index k = 0; k < zr.cols(); ++k) rmin[label[k]] = std::min(rmin[label[k]], zr(1, k));
  for (int c = 0; c < all; ++c)
    if (size[c] >= 3 || rmin[c] <= std::max(10 * merge, 1e-9 * out.size))
      keep[c] = m++, covered += size[c];
  if (m >= 2 && covered >= 0.8 * static_cast<double>(zr.cols()) && m <= zr.cols() / 3 + 2) {
    for (int& l : label) l = keep[l];
    out.rings = true;
    out.clusters = m;
    return ring_profile(zr, label, m, std::move(out), o, merge);
  }
  return scan_profile(zr, std::move(out), o);
}

MeridianDistances meridian_distances(const MeridianProfile& profile, const Eigen::Matrix2Xd& zr,
                                     int threads) {
  std::deque<CurveDistance<2>> dist;  // elements stay in place
  for (const MeridianLoop& l : profile.loops) dist.emplace_back(l.curve, l.closed);
  MeridianDistances out;
  out.distance.resize(zr.cols());
  out.normal.resize(2, zr.cols());
  out.loop.assign(static_cast<std::size_t>(zr.cols()), -1);
  const int chunks = worker_count(threads, static_cast<std::size_t>(zr.cols()));
  parallel_chunks(
      static_cast<std::size_t>(zr.cols()), chunks, [&](std::size_t b, std::size_t e, int) {
        for (std::size_t k = b; k < e; ++k) {
          const Eigen::Vector2d q = zr.col(static_cast<Eigen::Index>(k));
          double best = INFINITY, bu = 0;
          int bl = -1;
          for (std::size_t l = 0; l < dist.size(); ++l) {
            const auto f = dist[l].project(q);
            if (f.distance < best) best = f.distance, bu = f.u, bl = static_cast<int>(l);
          }
          const auto d = profile.loops[bl].curve.derivatives(bu, 1);
          const Eigen::Vector2d diff = q - d[0];
          Eigen::Vector2d n(-d[1].y(), d[1].x());
          n = n.norm() > 0 ? Eigen::Vector2d(n.normalized()) : Eigen::Vector2d(0, 1);
          const double along = n.dot(diff), len = diff.norm();
          const Eigen::Index i = static_cast<Eigen::Index>(k);
          if (len > 0 &&
              std::abs(along) < 0.99 * len) {  // beyond an end or a corner: the direction to q
            out.distance[i] = along < 0 ? -len : len;
            out.normal.col(i) = (along < 0 ? -1.0 : 1.0) * diff / len;
          } else {
            out.distance[i] = along;
            out.normal.col(i) = n;
          }
          out.loop[k] = bl;
        }
      });
  return out;
}

}  // namespace polarform
