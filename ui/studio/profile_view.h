// The cam profile view: the contour (coloured by pressure angle), pitch curve, base circle, the
// converted NURBS's control polygon, a curvature comb, and the follower (roller, knife edge or flat
// face) at a chosen cam angle — in the fixed frame, where the cam turns under the follower, or in
// the cam frame — with pan/zoom and a hover read-out. Cylindrical cams show the developed track.
#pragma once

#include <imgui.h>

#include "jobs/cam/cam_job.h"
#include "src/nurbs/nurbs_curve.h"
#include "ui/studio/cam_view_settings.h"
#include "ui/studio/view_2d.h"

namespace polarform::studio {

class ProfileView {
 public:
  // Fills the remaining content region. `converted` (may be null) is the NURBS profile whose
  // control polygon can be shown.
  void draw(const CamDesignStage& design, const CamAnalysisStage& analysis,
            const NurbsCurve2d* converted, CamViewSettings& view);

 private:
  void draw_toolbar(CamViewSettings& view, bool plate);
  void draw_plate(const PlateCam& cam, const CamAnalysisStage& a, const NurbsCurve2d* converted,
                  const CamViewSettings& view, ImVec2 min, ImVec2 max);
  void draw_barrel(const BarrelCam& cam, const CamAnalysisStage& a, const CamViewSettings& view,
                   ImVec2 min, ImVec2 max);
  void draw_follower(const PlateCam& cam, const CamAnalysis& analysis, const CamViewSettings& view,
                     ImDrawList* dl) const;
  void draw_arm(const PlateCam& cam, const CamAnalysis& analysis, double back,
                const Eigen::Vector2d& P, const Eigen::Vector2d& C, ImDrawList* dl) const;
  void draw_legend(const CamViewSettings& view, ImVec2 min, ImDrawList* dl) const;
  void hover_readout(const PlateCam& cam, const CamAnalysisStage& a,
                     const CamViewSettings& view) const;

  View2d view2d_;
  double rotation_ = 0.0;  // display rotation of cam-frame geometry this frame, rad
};

}  // namespace polarform::studio
