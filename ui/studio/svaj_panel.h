// The motion plots of the cam workspace: displacement, velocity, acceleration, jerk and pressure
// angle over one revolution, stacked on a shared θ axis with one crosshair, per radian or in time
// at the cam's speed. Segment boundaries are draggable markers (dragging one edits the design);
// every continuity issue is circled and explained on hover.
#pragma once

#include <imgui.h>

#include <array>
#include <vector>

#include "ui/studio/cam_results.h"
#include "ui/studio/cam_view_settings.h"
#include "ui/studio/plot_canvas.h"

namespace polarform::studio {

class SvajPanel {
 public:
  // Returns true when a boundary drag changed `segments`.
  bool draw(const CamResults& results, const CamViewSettings& view,
            std::vector<SegmentSpec>& segments, ImVec2 size);

 private:
  void convert_units(const CamResults& results, const CamViewSettings& view);

  AxisView x_view_;
  std::array<AxisView, 5> y_views_;
  Crosshair crosshair_;
  std::array<std::vector<double>, 3> scaled_;  // v, a, j in the chosen units
  std::array<double, 4> unit_factor_{1, 1, 1, 1};
};

}  // namespace polarform::studio
