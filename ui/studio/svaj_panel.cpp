#include "ui/studio/svaj_panel.h"

#include "jobs/cam/cam_plots.h"
#include "src/units.h"
#include "ui/studio/segment_edits.h"

namespace polarform::studio {

bool SvajPanel::draw(const CamDesignStage& design, const CamAnalysisStage& analysis,
                     std::uint64_t revision, const CamViewSettings& view,
                     std::vector<SegmentSpec>& segments, ImVec2 size) {
  if (!figure_ || revision != revision_ || view.units != units_ ||
      view.pressure_angle_limit != limit_) {
    SvajFigureOptions options;
    options.time_units = view.units == MotionUnits::time;
    options.pressure_panel = true;
    options.pressure_angle_limit = view.pressure_angle_limit;
    options.draggable_boundaries = true;
    figure_ = svaj_figure(design, analysis, options);
    revision_ = revision;
    units_ = view.units;
    limit_ = view.pressure_angle_limit;
  }
  const PlotEvents events = draw_figure("svaj", *figure_, view_, size);
  // The plots may show the last valid design while the edited one has fewer boundaries.
  if (events.dragged_handle > 0 && events.dragged_handle < static_cast<int>(segments.size())) {
    set_boundary(segments, events.dragged_handle, events.value * kRadiansPerDegree);
    return true;
  }
  return false;
}

}  // namespace polarform::studio
