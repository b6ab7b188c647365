// The app's window: GLFW with an OpenGL 3.3 core context, Dear ImGui with its GLFW and OpenGL3
// backends, fonts rebuilt when the content scale (DPI) changes, files dropped on the window
// collected for the app, and the frame begin/end around the app's drawing.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "ui/studio/persistent_state.h"

struct GLFWwindow;

namespace polarform::studio {

struct WindowConfig {
  std::string title = "polarform studio";
  WindowPlacement placement;
  bool vsync = true;
  // ImGui's own settings file; empty keeps ImGui from reading or writing one.
  std::string imgui_ini;
};

class PlatformWindow {
 public:
  // Throws std::runtime_error when GLFW, the window or the OpenGL 3.3 context cannot be created.
  explicit PlatformWindow(const WindowConfig& config);
  ~PlatformWindow();
  PlatformWindow(const PlatformWindow&) = delete;
  PlatformWindow& operator=(const PlatformWindow&) = delete;

  bool should_close() const;
  void request_close(bool close);
  void set_title(const std::string& title);

  // Polls events, rebuilds fonts after a DPI change and starts an ImGui frame. Headless runs
  // hide the mouse from ImGui, so that no hover read-out depends on where Xvfb left the pointer.
  void begin_frame(bool hide_mouse = false);
  // Renders ImGui's draw data into the back buffer (cleared first).
  void render();
  void swap();

  int framebuffer_width() const;
  int framebuffer_height() const;
  WindowPlacement placement() const;
  // Paths dropped on the window since the last call.
  std::vector<std::filesystem::path> take_dropped_files();
  // Files dropped on the window: what the window system's drop event delivers (and a script).
  void drop(std::vector<std::filesystem::path> files);

 private:
  static void on_drop(GLFWwindow* window, int count, const char** paths);
  static void on_content_scale(GLFWwindow* window, float x, float y);
  void rebuild_fonts();

  GLFWwindow* window_ = nullptr;
  std::string imgui_ini_;
  float scale_ = 1.0f;
  bool fonts_dirty_ = false;
  std::vector<std::filesystem::path> dropped_;
};

}  // namespace polarform::studio
