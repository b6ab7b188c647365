#include "src/fit/point_distances.h"

#include <vector>

namespace polarform {

PointDistances point_distances(const ProductGeometry& g, const Eigen::Matrix3Xd& local,
                               const Eigen::VectorXd& u, const Eigen::VectorXd& v, int threads,
                               ProgressRange progress) {
  const std::size_t n = static_cast<std::size_t>(local.cols());
  PointDistances out{Eigen::VectorXd(local.cols()), 0};
  const int chunks = worker_count(threads, n);
  std::vector<std::size_t> misses(static_cast<std::size_t>(chunks), 0);
  parallel_chunks(n, chunks, [&](std::size_t b, std::size_t e, int c) {
    for (std::size_t k = b; k < e; ++k) {
      const Eigen::Index i = static_cast<Eigen::Index>(k);
      const FootPoint fp = g.foot_point(local.col(i), u[i], v[i]);
      out.signed_distance[i] = fp.distance;
      if (!fp.converged) ++misses[static_cast<std::size_t>(c)];
      if (c == 0 && ((k - b) & 0x3FFF) == 0) progress(double(k - b) / double(e - b));
    }
  });
  for (std::size_t m : misses) out.unconverged += m;
  progress(1.0);
  return out;
}

}  // namespace polarform
