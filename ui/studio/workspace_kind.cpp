#include "ui/studio/workspace_kind.h"

namespace polarform::studio {

std::string_view workspace_name(WorkspaceKind kind) {
  switch (kind) {
    case WorkspaceKind::cam:
      return "cam";
    case WorkspaceKind::study:
      return "study";
    case WorkspaceKind::vessel:
      return "vessel";
    case WorkspaceKind::fit:
      return "fit";
  }
  return "cam";
}

std::string_view workspace_title(WorkspaceKind kind) {
  switch (kind) {
    case WorkspaceKind::cam:
      return "Cam";
    case WorkspaceKind::study:
      return "Study";
    case WorkspaceKind::vessel:
      return "Vessel";
    case WorkspaceKind::fit:
      return "Fit";
  }
  return "Cam";
}

std::optional<WorkspaceKind> parse_workspace(std::string_view name) {
  for (WorkspaceKind kind : kWorkspaces)
    if (workspace_name(kind) == name) return kind;
  return std::nullopt;
}

}  // namespace polarform::studio
