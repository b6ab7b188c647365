// The conversion panel of the cam workspace: the tolerance on a log-scale slider, the base arcs
// (quasi-uniform quartic or RQB) and their α rule, the function's share of the error budget; the
// result — arcs, degree, control points, measured radial and normal error against the tolerance,
// G1 check — and the measured radial error along the profile, magnified, with the arc junctions.
#pragma once

#include <imgui.h>

#include "ui/studio/cam_conversion.h"
#include "ui/studio/plot_canvas.h"

namespace polarform::studio {

class ConversionPanel {
 public:
  // The settings; true when one changed.
  bool draw_settings(ConversionOptions& options);
  // The result (null while none) and the message of a failed conversion.
  void draw_result(const CamConversion* conversion, const std::string& error, bool stale);
  void draw_error_plot(const CamConversion& conversion, ImVec2 size);

 private:
  AxisView x_view_, y_view_;
  bool log_scale_ = false;
};

}  // namespace polarform::studio
