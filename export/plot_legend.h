// The legend of a plot panel: one row per labelled series or band with a swatch drawn like the
// data (line, dash, marker shape, translucent fill), boxed and placed in the corner of the plot
// area that hides the least data.
#pragma once

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

// Draws the entries (duplicates once) in the corner of area where the box crosses the fewest
// segments and markers of `drawn` (pixel polylines; a marker is a one-point polyline).
void draw_legend(SvgWriter& svg, std::span<const LegendEntry> entries, const PixelRect& area,
                 std::span<const Polyline> drawn);

}  // namespace polarform
