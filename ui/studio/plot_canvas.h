// The app's 2-D plots: the jobs' figures (export/figure.h) drawn on ImDrawList — the same figures
// the SVG files show. Axes with nice ticks (export/plot_axis), labels with units, series decimated
// to pixel columns (lines, dashes, markers), reference lines, bands, highlighted points explained
// on hover, annotations, a hover read-out of every series at the cursor, wheel zoom about the
// cursor (over an axis: that axis only), drag to pan, double-click to fit the data again.
// Vertical lines that carry a handle can be dragged; the drag is reported, not applied. The
// panels of a figure with a shared x axis share one x view and one crosshair (SVAJ diagrams).
#pragma once

#include <imgui.h>

#include <optional>
#include <vector>

#include "export/figure.h"

namespace polarform::studio {

// The zoom/pan state of one axis; empty means "fit".
struct AxisView {
  std::optional<AxisRange> range;
};

// A crosshair shared by plots with a common x axis: the x under the mouse in any of them.
struct Crosshair {
  std::optional<double> x;     // this frame's, read by plots drawn after the hovered one
  std::optional<double> last;  // last frame's, read by plots drawn before it
  void next_frame() {
    last = x;
    x.reset();
  }
};

// What the user did to the plot's content this frame.
struct PlotEvents {
  int dragged_handle = -1;  // ReferenceLine::handle of a vertical line being dragged
  double value = 0.0;       // where it is dragged to (within the visible x range)
};

// Draws `plot` into a `size` rectangle at the cursor and handles its mouse input. `id` must be
// unique in the current ImGui ID scope; x tick labels and the x label are drawn when
// `x_tick_labels` (false for the upper panels of a shared x axis).
PlotEvents draw_plot(const char* id, const Plot& plot, AxisView& x_view, AxisView& y_view,
                     ImVec2 size, bool x_tick_labels = true, Crosshair* crosshair = nullptr);

// The views of a whole figure: one x view (shared axis) or one per panel, one y view per panel.
struct FigureView {
  std::vector<AxisView> x, y;
  Crosshair crosshair;
};

// Draws the figure's panels stacked in `size` (its title above them when it has one); panels of
// a shared x axis share one x view and a crosshair. Returns the first drag of any panel.
PlotEvents draw_figure(const char* id, const Figure& figure, FigureView& view, ImVec2 size);

}  // namespace polarform::studio
