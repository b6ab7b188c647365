// Drawing of one laid-out panel of a Figure: bands, grid, reference lines, the series (gaps at
// non-finite points, decimated to pixel columns, clipped to the plot area), the frame with ticks,
// tick labels, axis labels and title, annotations and the legend (inside where it hides nothing,
// else beside the plot area when the frame says so).
#pragma once

#include "export/figure.h"
#include "export/plot_layout.h"
#include "export/svg_writer.h"

namespace polarform {

void draw_panel(SvgWriter& svg, const Plot& plot, const PanelFrame& frame);

// Whether the panel's legend finds a place inside the plot area that hides nothing, and its width.
struct PanelLegendFit {
  double width = 0;  // 0: the panel has no legend
  bool inside = true;
};
PanelLegendFit panel_legend_fit(const Plot& plot, const PanelFrame& frame);

}  // namespace polarform
