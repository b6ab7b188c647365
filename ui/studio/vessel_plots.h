// The vessel workspace's plots: the head meridian in its plane (equal aspect, design and preset,
// cylinder and far side), curvature κ(θ) against the targets and the preset, the residual at
// each target, and the membrane stresses along the meridian with compressive hoop bands.
#pragma once

#include <imgui.h>

#include "ui/studio/plot_canvas.h"
#include "ui/studio/vessel_results.h"
#include "ui/studio/view_2d.h"

namespace polarform::studio {

class VesselPlots {
 public:
  void draw_meridian(const VesselResults& r, ImVec2 size);
  void draw_curvature(const VesselResults& r, ImVec2 size);
  void draw_residuals(const VesselResults& r, ImVec2 size);
  void draw_stresses(const VesselResults& r, ImVec2 size);

 private:
  View2d meridian_view_;
  AxisView curvature_x_, curvature_y_, residual_x_, residual_y_, stress_x_, stress_y_;
};

}  // namespace polarform::studio
