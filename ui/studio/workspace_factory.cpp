#include "ui/studio/workspace_factory.h"

#include "ui/studio/cam_workspace.h"
#include "ui/studio/fit_workspace.h"
#include "ui/studio/study_workspace.h"
#include "ui/studio/vessel_workspace.h"

namespace polarform::studio {

std::vector<std::unique_ptr<Workspace>> make_workspaces(StudioContext& context) {
  std::vector<std::unique_ptr<Workspace>> w;
  auto cam = std::make_unique<CamWorkspace>(context);
  auto study = std::make_unique<StudyWorkspace>(context, *cam);
  w.push_back(std::move(cam));
  w.push_back(std::move(study));
  w.push_back(std::make_unique<VesselWorkspace>(context));
  w.push_back(std::make_unique<FitWorkspace>(context));
  return w;
}

}  // namespace polarform::studio
