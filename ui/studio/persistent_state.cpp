#include "ui/studio/persistent_state.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "export/atomic_file.h"

namespace polarform::studio {
namespace {

std::optional<int> to_int(const std::string& text) {
  try {
    std::size_t used = 0;
    const int v = std::stoi(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

std::optional<float> to_float(const std::string& text) {
  try {
    std::size_t used = 0;
    const float v = std::stof(text, &used);
    if (used == text.size()) return v;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

}  // namespace

void PersistentState::remember(const std::filesystem::path& file, WorkspaceKind kind) {
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(file, ec);
  const std::filesystem::path& entry = ec ? file : absolute;
  recent.erase(std::remove(recent.begin(), recent.end(), entry), recent.end());
  recent.insert(recent.begin(), entry);
  if (recent.size() > kMaxRecent) recent.resize(kMaxRecent);
  last_project = entry;
  workspace = kind;
}

std::filesystem::path config_directory() {
  if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "polarform-studio";
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".config" / "polarform-studio";
  return std::filesystem::current_path() / ".polarform-studio";
}

PersistentState load_state(const std::filesystem::path& file) {
  PersistentState state;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find('=');
    if (eq == std::string::npos) continue;
    const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
    if (key == "last_project") {
      state.last_project = value;
    } else if (key == "workspace") {
      if (auto kind = parse_workspace(value)) state.workspace = *kind;
    } else if (key == "recent") {
      if (state.recent.size() < PersistentState::kMaxRecent && !value.empty())
        state.recent.emplace_back(value);
    } else if (key.starts_with("window.")) {
      const auto v = to_int(value);
      if (!v) continue;
      if (key == "window.x") state.window.x = *v;
      if (key == "window.y") state.window.y = *v;
      if (key == "window.width" && *v >= 320) state.window.width = *v;
      if (key == "window.height" && *v >= 240) state.window.height = *v;
      if (key == "window.maximized") state.window.maximized = *v != 0;
    } else if (key.starts_with("layout.")) {
      if (const auto v = to_float(value)) state.layout[key.substr(7)] = *v;
    }
  }
  return state;
}

void save_state(const PersistentState& state, const std::filesystem::path& file) {
  std::ostringstream out;
  out << "# polarform-studio state, rewritten on exit\n";
  out << "last_project=" << state.last_project.string() << "\n";
  out << "workspace=" << workspace_name(state.workspace) << "\n";
  for (const auto& r : state.recent) out << "recent=" << r.string() << "\n";
  out << "window.x=" << state.window.x << "\nwindow.y=" << state.window.y << "\n";
  out << "window.width=" << state.window.width << "\nwindow.height=" << state.window.height << "\n";
  out << "window.maximized=" << (state.window.maximized ? 1 : 0) << "\n";
  for (const auto& [key, value] : state.layout) out << "layout." << key << "=" << value << "\n";
  std::filesystem::create_directories(file.parent_path());
  write_file_atomically(file, out.str());
}

}  // namespace polarform::studio
