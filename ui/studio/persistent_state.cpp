#include "ui/studio/persistent_state.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>

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

// Applies one "key=value" line; false when the key is unknown or the value unreadable.
bool apply_line(PersistentState& state, const std::string& line) {
  const auto eq = line.find('=');
  if (eq == std::string::npos) return false;
  const std::string key = line.substr(0, eq), value = line.substr(eq + 1);
  if (key == "last_project") {
    state.last_project = value;
    return true;
  }
  if (key == "workspace") {
    const auto kind = parse_workspace(value);
    if (kind) state.workspace = *kind;
    return kind.has_value();
  }
  if (key == "recent") {
    if (value.empty()) return false;
    if (state.recent.size() < PersistentState::kMaxRecent) state.recent.emplace_back(value);
    return true;
  }
  if (key.starts_with("window.")) {
    const auto v = to_int(value);
    if (!v) return false;
    WindowPlacement& w = state.window;
    if (key == "window.x")
      w.x = *v;
    else if (key == "window.y")
      w.y = *v;
    else if (key == "window.width" && *v >= 320)
      w.width = *v;
    else if (key == "window.height" && *v >= 240)
      w.height = *v;
    else if (key == "window.maximized")
      w.maximized = *v != 0;
    else
      return false;
    return true;
  }
  if (key.starts_with("layout.") && key.size() > 7) {
    const auto v = to_float(value);
    if (v) state.layout[key.substr(7)] = *v;
    return v.has_value();
  }
  return false;
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

PersistentState load_state(const std::filesystem::path& file, MessageLog& log) {
  PersistentState state;
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return state;
  std::ifstream in;
  if (std::filesystem::is_regular_file(file, ec)) in.open(file);
  if (!in.is_open()) {
    log.warning(file.string() + ": cannot be read; the app starts with its default state");
    return state;
  }
  std::string line, first_ignored;
  int number = 0, ignored = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.ends_with('\r')) line.pop_back();  // edited on Windows
    if (line.empty() || line.starts_with('#')) continue;
    if (apply_line(state, line)) continue;
    if (ignored++ == 0) first_ignored = "line " + std::to_string(number) + " '" + line + "'";
  }
  if (ignored > 0)
    log.warning(file.string() + ": ignored " + std::to_string(ignored) + " unreadable line" +
                (ignored == 1 ? "" : "s") + " (first: " + first_ignored.substr(0, 120) +
                "); their settings keep the defaults");
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
  for (const auto& [key, value] : state.layout) {
    // The shortest text that reads back as the same float: 0.42, not 0.419999987.
    char shortest[32];
    const auto end = std::to_chars(shortest, shortest + sizeof shortest, value).ptr;
    out << "layout." << key << "=" << std::string_view(shortest, end - shortest) << "\n";
  }
  std::filesystem::create_directories(file.parent_path());
  write_file_atomically(file, out.str());
}

}  // namespace polarform::studio
