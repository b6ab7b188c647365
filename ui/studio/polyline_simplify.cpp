#include "ui/studio/polyline_simplify.h"

#include <cmath>

namespace polarform::studio {
namespace {

// Distance of p from the segment a-b, in pixels.
double distance_to_segment(const PixelPoint& p, const PixelPoint& a, const PixelPoint& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length2 : 0.0;
  t = std::fmin(1.0, std::fmax(0.0, t));
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

// True when every point strictly between `from` and `to` lies within `tolerance` of their chord.
bool chord_fits(const Polyline& points, std::size_t from, std::size_t to, double tolerance) {
  for (std::size_t i = from + 1; i < to; ++i)
    if (distance_to_segment(points[i], points[from], points[to]) > tolerance) return false;
  return true;
}

}  // namespace

Polyline simplify_polyline(const Polyline& points, double tolerance) {
  if (points.size() < 3) return points;
  Polyline out{points.front()};
  std::size_t anchor = 0;
  for (std::size_t end = 2; end < points.size(); ++end) {
    if (chord_fits(points, anchor, end, tolerance)) continue;
    anchor = end - 1;
    out.push_back(points[anchor]);
  }
  out.push_back(points.back());
  return out;
}

}  // namespace polarform::studio
