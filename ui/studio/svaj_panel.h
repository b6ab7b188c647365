// The motion plots of the cam workspace: the cam job's SVAJ figure — displacement, velocity,
// acceleration, jerk and pressure angle over one revolution, stacked on a shared θ axis with one
// crosshair, per radian or in time at the cam's speed — with every continuity issue circled and
// explained on hover. Segment boundaries are draggable (dragging one edits the design).
#pragma once

#include <imgui.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "jobs/cam/cam_job.h"
#include "ui/studio/cam_view_settings.h"
#include "ui/studio/plot_canvas.h"

namespace polarform::studio {

class SvajPanel {
 public:
  // Draws the figure of the stages (rebuilt when `revision` or the view's units or limit change).
  // Returns true when a boundary drag changed `segments`.
  bool draw(const CamDesignStage& design, const CamAnalysisStage& analysis, std::uint64_t revision,
            const CamViewSettings& view, std::vector<SegmentSpec>& segments, ImVec2 size);

 private:
  std::optional<Figure> figure_;
  std::uint64_t revision_ = 0;
  MotionUnits units_ = MotionUnits::per_radian;
  double limit_ = 0.0;
  FigureView view_;
};

}  // namespace polarform::studio
