// Drawing of one laid-out panel of a Figure: bands, grid, reference lines, the series (gaps at
// non-finite points, decimated to pixel columns, clipped to the plot area), the frame with ticks,
// tick labels, axis labels and title, annotations and the legend.
#pragma once

#include "export/figure.h"
#include "export/plot_layout.h"
#include "export/svg_writer.h"

namespace polarform {

void draw_panel(SvgWriter& svg, const Plot& plot, const PanelFrame& frame);

}  // namespace polarform
