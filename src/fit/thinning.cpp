// Thinning by a blanket's vertices (Piegl & Tiller 2001, §3.3; spec P7): the data point nearest
// to every vertex, found by ring search in a uniform 3D grid of the points, is kept.
#include "src/fit/thinning.h"

#include <algorithm>
#include <string>

#include "src/error.h"
#include "src/fit/grid_index.h"

namespace polarform {

// Piegl & Tiller 2001, §3.3: nearest point per vertex (ring search), the union of the marks.
Thinning thin_by_blanket(const Eigen::Matrix3Xd& points, const SurfaceBlanket& blanket) {
  const Eigen::Index vertices = blanket.points.cols();
  if (points.cols() == 0 || vertices == 0)
    throw InputError("thinning: " + std::to_string(points.cols()) + " points and " +
                     std::to_string(vertices) + " blanket vertices, expected both > 0");
  const GridIndex3d grid(points);
  std::vector<char> marked(static_cast<std::size_t>(points.cols()), 0);
  long long rings_total = 0;
  for (Eigen::Index k = 0; k < vertices; ++k) {
    int rings = 0;
    marked[grid.nearest(blanket.points.col(k), &rings)] = 1;
    rings_total += rings;
  }
  Thinning t;
  for (Eigen::Index i = 0; i < points.cols(); ++i)
    if (marked[i]) t.kept.push_back(static_cast<int>(i));
  t.vertices = static_cast<int>(vertices);
  t.mean_rings = static_cast<double>(rings_total) / static_cast<double>(vertices);
  return t;
}

}  // namespace polarform
