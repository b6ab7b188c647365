// The four workspaces of the app and their names on the command line and in menus: the cam
// designer, the tolerance study, the vessel designer and the surface fitter.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace polarform::studio {

enum class WorkspaceKind { cam, study, vessel, fit };

inline constexpr std::array<WorkspaceKind, 4> kWorkspaces = {
    WorkspaceKind::cam, WorkspaceKind::study, WorkspaceKind::vessel, WorkspaceKind::fit};

std::string_view workspace_name(WorkspaceKind kind);   // "cam", "study", "vessel", "fit"
std::string_view workspace_title(WorkspaceKind kind);  // "Cam", "Study", "Vessel", "Fit"
std::optional<WorkspaceKind> parse_workspace(std::string_view name);

}  // namespace polarform::studio
