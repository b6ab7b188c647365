// Turning data polylines, already mapped to pixels, into compact SVG path data: runs of finite
// points (non-finite points leave gaps), lossless decimation to the pixel columns, clipping to
// the plot area (no clipPath ids, no huge coordinates), and the "M x y L x y ..." text.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace polarform {

struct PixelPoint {
  double x, y;
  bool operator==(const PixelPoint&) const = default;
};

struct PixelRect {
  double left, top, right, bottom;  // top < bottom: SVG's y axis points down
  bool contains(PixelPoint p) const {
    return p.x >= left && p.x <= right && p.y >= top && p.y <= bottom;
  }
};

using Polyline = std::vector<PixelPoint>;

// The maximal runs of consecutive points whose coordinates are both finite.
std::vector<Polyline> finite_runs(std::span<const PixelPoint> points);

// Consecutive points that fall into the same 1-px column are reduced to the first, the lowest,
// the highest and the last of them, in their original order, which draws the same pixels while
// keeping every spike: the M4 aggregation of Jugel et al., VLDB 2014.
Polyline decimate_to_columns(std::span<const PixelPoint> run);

// Clips segment a-b to rect in place (Liang & Barsky 1984); false if nothing is inside.
bool clip_segment(PixelPoint& a, PixelPoint& b, const PixelRect& rect);

// The pieces of the polyline inside rect; a lone point inside stays a one-point piece.
std::vector<Polyline> clip_polyline(std::span<const PixelPoint> run, const PixelRect& rect);

// "M x y L x y ..." with one M per piece; a one-point piece is drawn as a zero-length segment,
// which a round line cap shows as a dot.
std::string path_data(std::span<const Polyline> pieces);

}  // namespace polarform
