// The workspaces this build of the app offers, in tab order. Each is created once and lives for
// the whole session.
#pragma once

#include <memory>
#include <vector>

#include "ui/studio/workspace.h"

namespace polarform::studio {

std::vector<std::unique_ptr<Workspace>> make_workspaces(StudioContext& context);

}  // namespace polarform::studio
