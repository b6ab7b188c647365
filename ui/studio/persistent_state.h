// What the app remembers between runs: the last project and workspace, the recent files, the
// window's placement and the layout (splitter fractions, view toggles). Stored as "key=value"
// lines in $XDG_CONFIG_HOME/polarform-studio/state.ini (~/.config when unset), next to ImGui's own
// imgui.ini. Unreadable or unknown lines are ignored with a warning in the log: a damaged file
// never stops the app.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ui/studio/message_log.h"
#include "ui/studio/workspace_kind.h"

namespace polarform::studio {

struct WindowPlacement {
  int x = -1, y = -1;  // -1: let the window manager choose
  int width = 1600, height = 1000;
  bool maximized = false;
};

struct PersistentState {
  std::filesystem::path last_project;
  WorkspaceKind workspace = WorkspaceKind::cam;
  std::vector<std::filesystem::path> recent;  // newest first, at most kMaxRecent
  WindowPlacement window;
  std::map<std::string, float> layout;  // named splitter fractions and toggles

  static constexpr std::size_t kMaxRecent = 10;

  // Moves `file` to the front of the recent list and makes it the last project.
  void remember(const std::filesystem::path& file, WorkspaceKind kind);
};

// The directory holding state.ini and imgui.ini.
std::filesystem::path config_directory();

// Defaults when the file is missing; defaults for whatever a damaged file does not say, with one
// warning naming the file, the number of ignored lines and the first of them.
PersistentState load_state(const std::filesystem::path& file, MessageLog& log);
// Written atomically; throws std::exception on an I/O failure.
void save_state(const PersistentState& state, const std::filesystem::path& file);

}  // namespace polarform::studio
