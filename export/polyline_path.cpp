#include "export/polyline_path.h"

#include <algorithm>
#include <cmath>

#include "export/svg_writer.h"

namespace polarform {

std::vector<Polyline> finite_runs(std::span<const PixelPoint> points) {
  std::vector<Polyline> runs;
  Polyline current;
  for (const PixelPoint& p : points) {
    if (std::isfinite(p.x) && std::isfinite(p.y)) {
      current.push_back(p);
    } else if (!current.empty()) {
      runs.push_back(std::move(current));
      current.clear();
    }
  }
  if (!current.empty()) runs.push_back(std::move(current));
  return runs;
}

Polyline decimate_to_columns(std::span<const PixelPoint> run) {
  Polyline kept;
  std::size_t begin = 0;
  while (begin < run.size()) {
    const double column = std::floor(run[begin].x);
    std::size_t end = begin + 1, lowest = begin, highest = begin;
    for (; end < run.size() && std::floor(run[end].x) == column; ++end) {
      if (run[end].y > run[lowest].y) lowest = end;  // SVG y grows downwards
      if (run[end].y < run[highest].y) highest = end;
    }
    std::size_t picks[] = {begin, lowest, highest, end - 1};
    std::sort(std::begin(picks), std::end(picks));
    for (std::size_t i = 0; i < 4; ++i)
      if (i == 0 || picks[i] != picks[i - 1]) kept.push_back(run[picks[i]]);
    begin = end;
  }
  return kept;
}

bool clip_segment(PixelPoint& a, PixelPoint& b, const PixelRect& rect) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  double t0 = 0, t1 = 1;
  // Each boundary as p·t <= q: left, right, top, bottom.
  const double p[] = {-dx, dx, -dy, dy};
  const double q[] = {a.x - rect.left, rect.right - a.x, a.y - rect.top, rect.bottom - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0) {
      if (q[i] < 0) return false;
    } else {
      const double t = q[i] / p[i];
      if (p[i] < 0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
    }
  }
  if (t0 > t1) return false;
  const PixelPoint start = a;
  if (t1 < 1) b = {start.x + t1 * dx, start.y + t1 * dy};
  if (t0 > 0) a = {start.x + t0 * dx, start.y + t0 * dy};
  return true;
}

std::vector<Polyline> clip_polyline(std::span<const PixelPoint> run, const PixelRect& rect) {
  std::vector<Polyline> pieces;
  if (run.size() == 1) {
    if (rect.contains(run[0])) pieces.push_back({run[0]});
    return pieces;
  }
  Polyline current;
  for (std::size_t i = 1; i < run.size(); ++i) {
    PixelPoint a = run[i - 1], b = run[i];
    if (!clip_segment(a, b, rect)) continue;
    if (!current.empty() && !(current.back() == a)) {
      pieces.push_back(std::move(current));
      current.clear();
    }
    if (current.empty()) current.push_back(a);
    current.push_back(b);
  }
  if (!current.empty()) pieces.push_back(std::move(current));
  return pieces;
}

std::string path_data(std::span<const Polyline> pieces) {
  std::string d;
  for (const Polyline& piece : pieces) {
    for (std::size_t i = 0; i < piece.size(); ++i)
      d.append(i == 0 ? "M" : "L")
          .append(svg_number(piece[i].x))
          .append(" ")
          .append(svg_number(piece[i].y));
    if (piece.size() == 1)
      d.append("L").append(svg_number(piece[0].x)).append(" ").append(svg_number(piece[0].y));
  }
  return d;
}

}  // namespace polarform
