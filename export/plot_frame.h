// The frame of one laid-out panel: grid lines at the ticks (drawn under the data), and the
// plot-area rectangle, tick marks, tick labels, axis labels, panel title and ×10ⁿ factors (drawn
// over it). The data layers are drawn by export/plot_panel.
#pragma once

#include "export/figure.h"
#include "export/plot_layout.h"
#include "export/svg_writer.h"

namespace polarform {

// Light grid at the major ticks, and at the minor ticks of log axes.
void draw_grid(SvgWriter& svg, const PanelFrame& frame);

// Frame, ticks and all labels of the panel.
void draw_frame(SvgWriter& svg, const Plot& plot, const PanelFrame& frame);

}  // namespace polarform
