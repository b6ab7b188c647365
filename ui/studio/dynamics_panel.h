// The dynamics of the cam workspace: the follower's load as the project states it (<dynamics>: the
// mass and spring of a translating follower, the inertia and torsion spring of an oscillating arm,
// the contact width and material), the job's key figures for it (cam_dynamics_figures, the words
// of report.html), and the contact force, camshaft torque and contact stress against cam angle
// (the figures of force.svg, torque.svg and stress.svg).
#pragma once

#include <imgui.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "jobs/cam/cam_job.h"
#include "ui/studio/plot_canvas.h"

namespace polarform::studio {

// Edits the project's load (none: no dynamics); returns true when it changed.
bool draw_dynamics_settings(std::optional<FollowerLoad>& load, FollowerKind follower);

// The key figures of the analysis's dynamics, or a hint when the project has none.
void draw_dynamics_summary(const CamDesignStage& design, const CamAnalysisStage& analysis);

class DynamicsPlots {
 public:
  // The force, torque and (with a contact width) stress figures, stacked in `size`; rebuilt when
  // `revision` changes.
  void draw(const CamDesignStage& design, const CamAnalysisStage& analysis, std::uint64_t revision,
            ImVec2 size);

 private:
  std::vector<Figure> figures_;
  std::vector<FigureView> views_;
  std::uint64_t revision_ = 0;
};

}  // namespace polarform::studio
