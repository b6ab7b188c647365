#include "ui/studio/workspace_kind.h"

namespace polarform::studio {

// In WorkspaceKind's order.
constexpr std::string_view kNames[] = {"cam", "study", "vessel", "fit"};
constexpr std::string_view kTitles[] = {"Cam", "Study", "Vessel", "Fit"};

std::string_view workspace_name(WorkspaceKind kind) { return kNames[static_cast<int>(kind)]; }

std::string_view workspace_title(WorkspaceKind kind) { return kTitles[static_cast<int>(kind)]; }

std::optional<WorkspaceKind> parse_workspace(std::string_view name) {
  for (WorkspaceKind kind : kWorkspaces)
    if (workspace_name(kind) == name) return kind;
  return std::nullopt;
}

}  // namespace polarform::studio
