#include "ui/studio/polyline_simplify.h"

#include <utility>
#include <vector>

namespace polarform::studio {
namespace {

// Squared distance of p from the segment a-b, in pixels².
double squared_distance_to_segment(const PixelPoint& p, const PixelPoint& a, const PixelPoint& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2 : 0.0;
  t = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  const double ex = p.x - (a.x + t * dx), ey = p.y - (a.y + t * dy);
  return ex * ex + ey * ey;
}

}  // namespace

// Douglas–Peucker (1973), iterative: a chord is kept when every point it replaces lies within
// the tolerance of it, else it is split at the farthest point.
Polyline simplify_polyline(const Polyline& points, double tolerance) {
  if (points.size() < 3) return points;
  const double tolerance2 = tolerance * tolerance;
  std::vector<bool> keep(points.size(), false);
  keep.front() = keep.back() = true;
  std::vector<std::pair<std::size_t, std::size_t>> chords{{0, points.size() - 1}};
  while (!chords.empty()) {
    const auto [from, to] = chords.back();
    chords.pop_back();
    double farthest2 = tolerance2;
    std::size_t split = 0;
    for (std::size_t i = from + 1; i < to; ++i) {
      const double d2 = squared_distance_to_segment(points[i], points[from], points[to]);
      if (d2 > farthest2) farthest2 = d2, split = i;
    }
    if (split == 0) continue;
    keep[split] = true;
    chords.emplace_back(from, split);
    chords.emplace_back(split, to);
  }
  Polyline out;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (keep[i]) out.push_back(points[i]);
  return out;
}

}  // namespace polarform::studio
