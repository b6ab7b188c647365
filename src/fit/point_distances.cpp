#include "src/fit/point_distances.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace polarform {

namespace {

// The restart of a foot-point search that hit its iteration limit: the closest of a 9 x 9 grid of
// parameters spanning a fifth of the domain around the start, then Gauss–Newton from there
// (Piegl & Tiller 2001, §3.2: a coarse search brackets the closest point before the iteration).
FootPoint restarted_foot_point(const ProductGeometry& g, const Eigen::Vector3d& P, double u,
                               double v) {
  const double hu = 0.1 * (g.back_u() - g.front_u()), hv = 0.1 * (g.back_v() - g.front_v());
  double best = HUGE_VAL, bu = u, bv = v;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) {
      const double cu = std::clamp(u + hu * i / 4.0, g.front_u(), g.back_u());
      const double cv = std::clamp(v + hv * j / 4.0, g.front_v(), g.back_v());
      const double d = (g.point(cu, cv) - P).squaredNorm();
      if (d < best) best = d, bu = cu, bv = cv;
    }
  return g.foot_point(P, bu, bv);
}

}  // namespace

PointDistances point_distances(const ProductGeometry& g, const Eigen::Matrix3Xd& local,
                               const Eigen::VectorXd& u, const Eigen::VectorXd& v, int threads,
                               ProgressRange progress) {
  const std::size_t n = static_cast<std::size_t>(local.cols());
  PointDistances out{Eigen::VectorXd(local.cols()), 0};
  const int chunks = worker_count(threads, n);
  std::vector<std::size_t> misses(static_cast<std::size_t>(chunks), 0), restarts(misses);
  parallel_chunks(n, chunks, [&](std::size_t b, std::size_t e, int c) {
    for (std::size_t k = b; k < e; ++k) {
      const Eigen::Index i = static_cast<Eigen::Index>(k);
      FootPoint fp = g.foot_point(local.col(i), u[i], v[i]);
      if (!fp.converged) {
        const FootPoint again = restarted_foot_point(g, local.col(i), u[i], v[i]);
        if (again.converged || std::abs(again.distance) < std::abs(fp.distance)) fp = again;
        ++(fp.converged ? restarts : misses)[static_cast<std::size_t>(c)];
      }
      out.signed_distance[i] = fp.distance;
      if (c == 0 && ((k - b) & 0x3FFF) == 0) progress(double(k - b) / double(e - b));
    }
  });
  for (std::size_t m : misses) out.unconverged += m;
  for (std::size_t m : restarts) out.restarted += m;
  progress(1.0);
  return out;
}

}  // namespace polarform
