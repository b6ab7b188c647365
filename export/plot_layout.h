// Layout of a Figure: the ranges of every panel's axes (x fitted to the data, y with 5 % margins,
// equal aspect, a shared x axis), the pixel rectangle of each plot area after room for titles,
// tick labels and axis labels, and the ticks of every axis.
#pragma once

#include <string>
#include <vector>

#include "export/figure.h"
#include "export/nice_ticks.h"
#include "export/plot_axis.h"
#include "export/polyline_path.h"

namespace polarform {

struct PanelFrame {
  PixelRect area;  // the plot area; integer pixel edges
  AxisScale x, y;
  TickSet x_ticks, y_ticks;
  bool x_tick_labels;   // false in the upper panels of a shared-x stack
  std::string x_label;  // drawn under the panel; empty in those upper panels
  bool legend_outside = false;  // the legend goes right of the area, in the reserved room
};

// Distance of the figure title's baseline and of the y labels' centre line from the edges.
inline constexpr double kFigurePadding = 10;

// One frame per panel, top to bottom, leaving `right_room` pixels right of the plot areas (for
// legends beside them). Throws InputError for settings that cannot be drawn.
std::vector<PanelFrame> lay_out_figure(const Figure& figure, double right_room = 0);

}  // namespace polarform
