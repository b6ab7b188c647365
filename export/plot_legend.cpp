#include "export/plot_legend.h"

#include <algorithm>

#include "export/plot_style.h"
#include "export/text_width.h"

namespace polarform {

namespace {

namespace style = plot_style;

constexpr double kInset = 8;    // from the plot area's edges
constexpr double kPadding = 7;  // inside the box
constexpr double kRow = 17;
constexpr double kSwatch = 26;
constexpr double kGap = 6;  // between swatch and text

bool overlaps(const PixelRect& a, const PixelRect& b) {
  return a.left < b.right && b.left < a.right && a.top < b.bottom && b.top < a.bottom;
}

// How much of the obstacles a box at rect would hide.
int covered(const PixelRect& rect, const LegendObstacles& obstacles) {
  int count = 0;
  for (const Polyline& line : obstacles.lines) {
    if (line.size() == 1) count += rect.contains(line[0]);
    for (std::size_t i = 1; i < line.size(); ++i) {
      PixelPoint a = line[i - 1], b = line[i];
      count += clip_segment(a, b, rect);
    }
  }
  for (const PixelRect& box : obstacles.boxes) count += overlaps(rect, box);
  return count;
}

PixelRect box_at(const Legend& legend, PixelPoint p) {
  return {p.x, p.y, p.x + legend.width, p.y + legend.height};
}

// Top right first: ties keep the conventional place.
std::vector<PixelPoint> corners(const Legend& legend, const PixelRect& area) {
  const double left = area.left + kInset, right = area.right - kInset - legend.width;
  const double top = area.top + kInset, bottom = area.bottom - kInset - legend.height;
  return {{right, top}, {left, top}, {right, bottom}, {left, bottom}};
}

void draw_swatch(SvgWriter& svg, const LegendEntry& e, double x, double y) {
  using Kind = LegendEntry::Kind;
  if (e.kind == Kind::band) {
    svg.begin("rect")
        .attr("x", x)
        .attr("y", y - 5)
        .attr("width", kSwatch)
        .attr("height", 10)
        .attr("fill", e.color)
        .attr("fill-opacity", style::band_opacity)
        .empty();
    return;
  }
  if (e.kind != Kind::markers) {
    svg.begin("path")
        .attr("d", "M" + svg_number(x) + " " + svg_number(y) + "H" + svg_number(x + kSwatch))
        .attr("stroke", e.color)
        .attr("stroke-width", style::line_width);
    if (e.kind == Kind::dashed) svg.attr("stroke-dasharray", style::dash);
    svg.empty();
  }
  if (e.kind == Kind::markers || e.kind == Kind::line_markers)
    svg.begin("path")
        .attr("d", marker_path(e.shape, {x + kSwatch / 2, y}, style::marker_radius))
        .attr("fill", e.color)
        .attr("stroke", "white")
        .attr("stroke-width", 0.75)
        .empty();
}

}  // namespace

Legend make_legend(std::span<const LegendEntry> entries) {
  Legend legend;
  for (const LegendEntry& e : entries)
    if (std::find(legend.rows.begin(), legend.rows.end(), e) == legend.rows.end())
      legend.rows.push_back(e);
  if (legend.empty()) return legend;
  double text = 0;
  for (const LegendEntry& e : legend.rows)
    text = std::max(text, text_width(e.label, style::legend_font));
  legend.width = 2 * kPadding + kSwatch + kGap + text;
  legend.height = 2 * kPadding + kRow * static_cast<double>(legend.rows.size()) - 4;
  return legend;
}

std::optional<PixelPoint> free_legend_place(const Legend& legend, const PixelRect& area,
                                            const LegendObstacles& obstacles) {
  std::vector<PixelPoint> places = corners(legend, area);
  const double middle = 0.5 * (area.left + area.right - legend.width);
  places.push_back({middle, places[0].y});
  places.push_back({middle, places[2].y});
  for (const PixelPoint& p : places) {
    const PixelRect box = box_at(legend, p);
    if (box.left >= area.left && box.right <= area.right && box.top >= area.top &&
        box.bottom <= area.bottom && covered(box, obstacles) == 0)
      return p;
  }
  return std::nullopt;
}

PixelPoint least_covering_legend_place(const Legend& legend, const PixelRect& area,
                                       const LegendObstacles& obstacles) {
  PixelPoint best{};
  int least = -1;
  for (const PixelPoint& c : corners(legend, area)) {
    const int count = covered(box_at(legend, c), obstacles);
    if (least < 0 || count < least) {
      least = count;
      best = c;
    }
  }
  return best;
}

PixelPoint outside_legend_place(const PixelRect& area) { return {area.right + kInset, area.top}; }

double outside_legend_room(double legend_width) { return kInset + legend_width; }

void draw_legend(SvgWriter& svg, const Legend& legend, PixelPoint best) {
  if (legend.empty()) return;
  const std::vector<LegendEntry>& rows = legend.rows;
  svg.begin("g").attr("class", "legend").attr("font-size", style::legend_font).open();
  svg.begin("rect")
      .attr("x", best.x)
      .attr("y", best.y)
      .attr("width", legend.width)
      .attr("height", legend.height)
      .attr("rx", 3)
      .attr("fill", "white")
      .attr("fill-opacity", 0.9)
      .attr("stroke", "#cccccc")
      .empty();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double y = best.y + kPadding + kRow * (static_cast<double>(i) + 0.5) - 2;
    draw_swatch(svg, rows[i], best.x + kPadding, y);
    svg.begin("text")
        .attr("x", best.x + kPadding + kSwatch + kGap)
        .attr("y", y)
        .attr("dy", "0.35em")
        .attr("fill", style::text_color)
        .text(rows[i].label);
  }
  svg.close();
}

}  // namespace polarform
