// The legend of a plot panel: one row per labelled series or band with a swatch drawn like the
// data (line, dash, marker shape, translucent fill), boxed, and placed where it hides nothing —
// inside the plot area where it covers no data, annotation or label, else beside it, in room the
// layout keeps free for it (svg_plot.cpp).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "export/figure.h"
#include "export/plot_marks.h"
#include "export/polyline_path.h"
#include "export/svg_writer.h"

namespace polarform {

struct LegendEntry {
  enum class Kind { line, dashed, markers, line_markers, band };
  Kind kind;
  std::string label;
  std::string color;
  MarkerShape shape = MarkerShape::circle;
  bool operator==(const LegendEntry&) const = default;
};

// The rows (each entry once) and the size of their box in pixels.
struct Legend {
  std::vector<LegendEntry> rows;
  double width = 0, height = 0;
  bool empty() const { return rows.empty(); }
};

Legend make_legend(std::span<const LegendEntry> entries);

// What a legend must not hide: pixel polylines (data; a marker is a one-point polyline) and
// boxes (annotations with their text, highlight rings, reference-line labels).
struct LegendObstacles {
  std::vector<Polyline> lines;
  std::vector<PixelRect> boxes;
};

// Where the legend's box (its top-left corner) covers nothing inside area: the corners (top right,
// top left, bottom right, bottom left), then the middles of the top and bottom edges; nullopt when
// every place covers something.
std::optional<PixelPoint> free_legend_place(const Legend& legend, const PixelRect& area,
                                            const LegendObstacles& obstacles);
// The corner of area whose box covers the fewest obstacles: the last resort when no place is
// free and the figure has no room beside the plot.
PixelPoint least_covering_legend_place(const Legend& legend, const PixelRect& area,
                                       const LegendObstacles& obstacles);
// Beside area, right of it and level with its top: in the room lay_out_figure reserved.
PixelPoint outside_legend_place(const PixelRect& area);
// Room to reserve right of the plot area for a legend of this width.
double outside_legend_room(double legend_width);

void draw_legend(SvgWriter& svg, const Legend& legend, PixelPoint top_left);

}  // namespace polarform
