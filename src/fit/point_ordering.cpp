// Ordered subset selection of a thin 2D band (Kantz 2003, §4.1; Lee 2000).
#include "src/fit/point_ordering.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <numeric>

#include "src/fit/grid_index.h"

namespace polarform {

namespace {

Eigen::Vector2d tls_direction(const Eigen::Matrix2Xd& P, const std::vector<int>& idx) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (int i : idx) mean += P.col(i);
  mean /= static_cast<double>(idx.size());
  Eigen::Matrix2d S = Eigen::Matrix2d::Zero();
  for (int i : idx) S += (P.col(i) - mean) * (P.col(i) - mean).transpose();
  return Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(S).eigenvectors().col(1);
}

}  // namespace

// Lee 2000 / Kantz 2003, §4.1, Figs. 4.4–4.5.
std::vector<OrderedChain> order_points(const Eigen::Matrix2Xd& P, double r, int min_points) {
  const Eigen::Index n = P.cols();
  std::vector<OrderedChain> chains;
  if (n == 0) return chains;
  const GridIndex2d grid(P);
  std::vector<char> visited(static_cast<std::size_t>(n), 0);
  std::vector<int> by_x(static_cast<std::size_t>(n));
  std::iota(by_x.begin(), by_x.end(), 0);
  std::sort(by_x.begin(), by_x.end(), [&](int a, int b) {
    return P(0, a) != P(0, b) ? P(0, a) < P(0, b) : P(1, a) < P(1, b);
  });
  std::vector<int> all, nb;
  std::vector<std::vector<int>> groups;  // per node: the points it took
  // One step from `cur`: takes its unvisited neighbours, returns the farthest on the +dir side.
  auto step = [&](int cur, Eigen::Vector2d& dir, std::vector<int>& taken, int& back) {
    grid.radius(P.col(cur), r, all);
    Eigen::Vector2d d = all.size() >= 2 ? tls_direction(P, all) : dir;
    if (d.dot(dir) < 0) d = -d;
    dir = d;
    nb.clear();
    for (int i : all)
      if (!visited[i]) nb.push_back(i);
    int fwd = -1;
    back = -1;
    double best_f = 0.0, best_b = 0.0;
    for (int i : nb) {
      const double t = (P.col(i) - P.col(cur)).dot(d);
      if (t > best_f) best_f = t, fwd = i;
      if (t < best_b) best_b = t, back = i;
      visited[i] = 1;
      taken.push_back(i);
    }
    return fwd;
  };
  for (int s : by_x) {
    if (visited[s]) continue;
    std::vector<int> fwd_nodes{s}, bwd_nodes;
    std::vector<std::vector<int>> fwd_groups(1), bwd_groups;
    Eigen::Vector2d dir = Eigen::Vector2d::UnitX();
    int back = -1;
    visited[s] = 1;
    fwd_groups[0].push_back(s);
    int next = step(s, dir, fwd_groups[0], back);
    const Eigen::Vector2d start_dir = dir;
    for (int cur = next; cur >= 0; cur = next) {  // forward
      fwd_nodes.push_back(cur);
      fwd_groups.emplace_back();
      int ignored = -1;
      next = step(cur, dir, fwd_groups.back(), ignored);
    }
    dir = -start_dir;
    for (int cur = back; cur >= 0; cur = next) {  // backward from the start's far side
      bwd_nodes.push_back(cur);
      bwd_groups.emplace_back();
      int ignored = -1;
      next = step(cur, dir, bwd_groups.back(), ignored);
    }
    OrderedChain c;
    c.nodes.assign(bwd_nodes.rbegin(), bwd_nodes.rend());
    c.nodes.insert(c.nodes.end(), fwd_nodes.begin(), fwd_nodes.end());
    groups.assign(bwd_groups.rbegin(), bwd_groups.rend());
    groups.insert(groups.end(), fwd_groups.begin(), fwd_groups.end());
    // Each node's points in order along the chain's direction there.
    const int m = static_cast<int>(c.nodes.size());
    for (int k = 0; k < m; ++k) {
      const Eigen::Vector2d a = P.col(c.nodes[std::max(0, k - 1)]);
      const Eigen::Vector2d b = P.col(c.nodes[std::min(m - 1, k + 1)]);
      const Eigen::Vector2d t = m > 1 ? Eigen::Vector2d(b - a) : start_dir;
      auto& g = groups[static_cast<std::size_t>(k)];
      std::sort(g.begin(), g.end(),
                [&](int x, int y) { return P.col(x).dot(t) < P.col(y).dot(t); });
      c.points.insert(c.points.end(), g.begin(), g.end());
    }
    c.closed = m >= 4 && (P.col(c.nodes.front()) - P.col(c.nodes.back())).norm() <= 2 * r;
    if (static_cast<int>(c.points.size()) >= min_points) chains.push_back(std::move(c));
  }
  std::stable_sort(chains.begin(), chains.end(), [](const OrderedChain& a, const OrderedChain& b) {
    return a.points.size() > b.points.size();
  });
  return chains;
}

}  // namespace polarform
