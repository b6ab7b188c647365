#include "ui/studio/platform_window.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <iterator>
#include <stdexcept>
#include <utility>

#include "ui/studio/font_setup.h"
#include "ui/studio/gl_api.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace polarform::studio {
namespace {

void glfw_error(int code, const char* text) {
  (void)code;
  fprintf(stderr, "polarform-studio: GLFW: %s\n", text);
}

}  // namespace

PlatformWindow::PlatformWindow(const WindowConfig& config) : imgui_ini_(config.imgui_ini) {
  glfwSetErrorCallback(glfw_error);
  if (!glfwInit())
    throw std::runtime_error("cannot initialise GLFW (is there a display? try xvfb-run)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  glfwWindowHint(GLFW_MAXIMIZED, config.placement.maximized ? GLFW_TRUE : GLFW_FALSE);
  // ImGui draws without depth or stencil and the 3D views render into their own framebuffers:
  // the window needs neither, and a software renderer then has no depth buffer to clear.
  glfwWindowHint(GLFW_DEPTH_BITS, 0);
  glfwWindowHint(GLFW_STENCIL_BITS, 0);
  window_ = glfwCreateWindow(config.placement.width, config.placement.height, config.title.c_str(),
                             nullptr, nullptr);
  if (!window_) {
    glfwTerminate();
    throw std::runtime_error("cannot create a window with an OpenGL 3.3 core context");
  }
  if (config.placement.x >= 0 && config.placement.y >= 0 && !config.placement.maximized)
    glfwSetWindowPos(window_, config.placement.x, config.placement.y);
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(config.vsync ? 1 : 0);
  glfwSetWindowUserPointer(window_, this);
  glfwSetDropCallback(window_, on_drop);
  glfwSetWindowContentScaleCallback(window_, on_content_scale);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = imgui_ini_.empty() ? nullptr : imgui_ini_.c_str();
  io.ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
  float sx = 1.0f, sy = 1.0f;
  glfwGetWindowContentScale(window_, &sx, &sy);
  scale_ = std::max(sx, sy);
  build_fonts(scale_);
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
}

PlatformWindow::~PlatformWindow() {
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  glfwTerminate();
}

bool PlatformWindow::should_close() const { return glfwWindowShouldClose(window_); }
void PlatformWindow::request_close(bool close) {
  glfwSetWindowShouldClose(window_, close ? GLFW_TRUE : GLFW_FALSE);
}
void PlatformWindow::set_title(const std::string& title) {
  glfwSetWindowTitle(window_, title.c_str());
}

void PlatformWindow::begin_frame(bool hide_mouse) {
  glfwPollEvents();
  if (fonts_dirty_) rebuild_fonts();
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  if (hide_mouse) ImGui::GetIO().MousePos = ImVec2(-FLT_MAX, -FLT_MAX);
  ImGui::NewFrame();
}

void PlatformWindow::render() {
  ImGui::Render();
  glViewport(0, 0, framebuffer_width(), framebuffer_height());
  const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
  glClearColor(bg.x, bg.y, bg.z, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void PlatformWindow::swap() { glfwSwapBuffers(window_); }

int PlatformWindow::framebuffer_width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}

int PlatformWindow::framebuffer_height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

WindowPlacement PlatformWindow::placement() const {
  WindowPlacement p;
  p.maximized = glfwGetWindowAttrib(window_, GLFW_MAXIMIZED) == GLFW_TRUE;
  glfwGetWindowPos(window_, &p.x, &p.y);
  glfwGetWindowSize(window_, &p.width, &p.height);
  return p;
}

std::vector<std::filesystem::path> PlatformWindow::take_dropped_files() {
  return std::exchange(dropped_, {});
}

void PlatformWindow::drop(std::vector<std::filesystem::path> files) {
  dropped_.insert(dropped_.end(), std::make_move_iterator(files.begin()),
                  std::make_move_iterator(files.end()));
}

void PlatformWindow::on_drop(GLFWwindow* window, int count, const char** paths) {
  auto* self = static_cast<PlatformWindow*>(glfwGetWindowUserPointer(window));
  self->drop(std::vector<std::filesystem::path>(paths, paths + count));
}

void PlatformWindow::on_content_scale(GLFWwindow* window, float x, float y) {
  auto* self = static_cast<PlatformWindow*>(glfwGetWindowUserPointer(window));
  self->scale_ = std::max(x, y);
  self->fonts_dirty_ = true;
}

void PlatformWindow::rebuild_fonts() {
  fonts_dirty_ = false;
  build_fonts(scale_);
  ImGui_ImplOpenGL3_DestroyFontsTexture();
  ImGui_ImplOpenGL3_CreateFontsTexture();
}

}  // namespace polarform::studio
