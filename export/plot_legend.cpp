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

// How much of the drawn data a box at rect would hide.
int covered(const PixelRect& rect, std::span<const Polyline> drawn) {
  int count = 0;
  for (const Polyline& line : drawn) {
    if (line.size() == 1) count += rect.contains(line[0]);
    for (std::size_t i = 1; i < line.size(); ++i) {
      PixelPoint a = line[i - 1], b = line[i];
      count += clip_segment(a, b, rect);
    }
  }
  return count;
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

void draw_legend(SvgWriter& svg, std::span<const LegendEntry> entries, const PixelRect& area,
                 std::span<const Polyline> drawn) {
  std::vector<LegendEntry> rows;
  for (const LegendEntry& e : entries)
    if (std::find(rows.begin(), rows.end(), e) == rows.end()) rows.push_back(e);
  if (rows.empty()) return;

  double text = 0;
  for (const LegendEntry& e : rows) text = std::max(text, text_width(e.label, style::legend_font));
  const double width = 2 * kPadding + kSwatch + kGap + text;
  const double height = 2 * kPadding + kRow * static_cast<double>(rows.size()) - 4;
  const double left = area.left + kInset, right = area.right - kInset - width;
  const double top = area.top + kInset, bottom = area.bottom - kInset - height;
  // Top right first: ties keep the conventional place.
  const PixelPoint corners[] = {{right, top}, {left, top}, {right, bottom}, {left, bottom}};
  PixelPoint best = corners[0];
  int least = -1;
  for (const PixelPoint& c : corners) {
    const int count = covered({c.x, c.y, c.x + width, c.y + height}, drawn);
    if (least < 0 || count < least) {
      least = count;
      best = c;
    }
  }

  svg.begin("g").attr("class", "legend").attr("font-size", style::legend_font).open();
  svg.begin("rect")
      .attr("x", best.x)
      .attr("y", best.y)
      .attr("width", width)
      .attr("height", height)
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
