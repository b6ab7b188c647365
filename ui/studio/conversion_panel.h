// The conversion panel of the cam workspace: the tolerance on a log-scale slider, the base arcs
// (quasi-uniform quartic or RQB) and their α rule, the function's share of the error budget; the
// result — arcs, degree, control points, measured radial and normal error against the tolerance,
// G1 check — and the cam job's figure of the measured radial error along the profile, with the
// arc junctions. The vessel workspace shows its conversion with the same table.
#pragma once

#include <imgui.h>

#include <cstdint>
#include <optional>
#include <string>

#include "jobs/cam/cam_job.h"
#include "ui/studio/plot_canvas.h"

namespace polarform::studio {

class ConversionPanel {
 public:
  // The settings; true when one changed.
  bool draw_settings(ConversionOptions& options);
  // The result (null while none) — degree and control points of the exported curve — and the
  // message of a failed conversion.
  void draw_result(const PolarConversion* conversion, int degree, int control_points,
                   const std::string& error, bool stale);
  // The stage's error figure, rebuilt when the scale or the stage's `revision` changes.
  void draw_error_plot(const CamConversionStage& conversion, std::uint64_t revision, ImVec2 size);

 private:
  FigureView view_;
  bool log_scale_ = false;
  std::optional<Figure> figure_;
  std::uint64_t figure_revision_ = 0;
};

}  // namespace polarform::studio
