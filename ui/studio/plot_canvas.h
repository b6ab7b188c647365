// The app's 2-D plots, drawn on ImDrawList: axes with nice ticks (export/plot_axis), labels with
// units, line series decimated to pixel columns, vertical markers (segment boundaries), bands and
// highlighted points (discontinuities, violations), a hover read-out of every series at the
// cursor, wheel zoom about the cursor (over an axis: that axis only), drag to pan, double-click
// to fit the data again; draggable markers follow the mouse. Several plots may share one x view and
// one crosshair (SVAJ diagrams).
#pragma once

#include <imgui.h>

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "export/svg_plot.h"

namespace polarform::studio {

struct PlotLine {
  std::string label;
  std::span<const double> x, y;  // equal lengths, x ascending; non-finite values leave gaps
  ImU32 color = 0;
  float thickness = 2.0f;  // whole pixels: ImGui draws those as cheap textured lines
};

struct PlotMarker {  // vertical line at x
  double x = 0.0;
  std::string label;  // shown in the hover read-out near the line
  ImU32 color = 0;
  bool draggable = false;  // the user may drag it along x (see PlotEvents)
};

struct PlotLevel {  // horizontal line at y
  double y = 0.0;
  std::string label;
  ImU32 color = 0;
};

struct PlotBand {  // highlighted x range
  double x0 = 0.0, x1 = 0.0;
  ImU32 color = 0;
};

struct PlotPoint {  // a highlighted point with its explanation
  double x = 0.0, y = 0.0;
  std::string text;
  ImU32 color = 0;
  bool small = false;  // a dot (many data points) instead of a circle (a few highlights)
};

struct PlotSpec {
  const char* id = "plot";
  std::string title;
  std::string x_label, y_label;  // with units: "θ [deg]", "s [mm]"
  bool log_x = false, log_y = false;
  bool x_tick_labels = true;          // false for stacked plots above a shared x axis
  std::optional<AxisRange> x_extent;  // what "fit" shows in x; default: the data
  std::optional<AxisRange> y_extent;  // what "fit" shows in y; default: the visible data + 5 %
  std::vector<PlotLine> lines;
  std::vector<PlotMarker> markers;
  std::vector<PlotLevel> levels;
  std::vector<PlotBand> bands;
  std::vector<PlotPoint> points;
};

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
  int dragged_marker = -1;  // index into spec.markers of a draggable marker being dragged
  double marker_x = 0.0;    // where it is dragged to (within the visible x range)
};

// Draws the plot into a `size` rectangle at the cursor and handles its mouse input.
PlotEvents draw_plot(const PlotSpec& spec, AxisView& x_view, AxisView& y_view, ImVec2 size,
                     Crosshair* crosshair = nullptr);

}  // namespace polarform::studio
