#include "ui/studio/app.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <thread>
#include <utility>

#include "ui/studio/document_kind.h"
#include "ui/studio/frame_statistics.h"
#include "ui/studio/gl_api.h"
#include "ui/studio/guarded.h"
#include "ui/studio/png_capture.h"
#include "ui/studio/splitter.h"
#include "ui/studio/template_picker.h"
#include "ui/studio/workspace_factory.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

namespace polarform::studio {
namespace {

using Clock = std::chrono::steady_clock;

double milliseconds_since(Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

WindowConfig window_config(const StudioOptions& options, const PersistentState& state, bool persist,
                           const std::filesystem::path& state_file) {
  WindowConfig config;
  config.placement = persist ? state.window : WindowPlacement{};
  if (options.size_given || !persist) {
    config.placement.width = options.width;
    config.placement.height = options.height;
    config.placement.maximized = false;
  }
  config.vsync = !options.headless();
  if (persist) config.imgui_ini = (state_file.parent_path() / "imgui.ini").string();
  return config;
}

// examples/ of the source tree, or $POLARFORM_EXAMPLES.
std::filesystem::path examples_directory() {
  if (const char* dir = std::getenv("POLARFORM_EXAMPLES"); dir && *dir) return dir;
  return POLARFORM_EXAMPLES_DIR;
}

}  // namespace

App::App(StudioOptions options)
    : options_(std::move(options)),
      persist_(!options_.headless() || options_.state_dir),
      state_file_(options_.state_dir.value_or(config_directory()) / "state.ini"),
      state_(persist_ ? load_state(state_file_, log_) : PersistentState{}),
      context_{log_, state_.layout, examples_directory()} {
  if (persist_) {
    std::error_code ec;
    std::filesystem::create_directories(state_file_.parent_path(), ec);
  }
  window_ =
      std::make_unique<PlatformWindow>(window_config(options_, state_, persist_, state_file_));
  context_.open_as_template = [this](const std::filesystem::path& file) {
    open_document(file, true);
  };
  workspaces_ = make_workspaces(context_);
  active_ = persist_ ? state_.workspace : WorkspaceKind::cam;

  // The document: the one asked for, else the last one, else the first cam template.
  if (options_.project) {
    open_document(*options_.project);
  } else if (persist_ && !state_.last_project.empty() &&
             std::filesystem::exists(state_.last_project)) {
    const WorkspaceKind last_workspace = state_.workspace;  // opening remembers the project's own
    open_document(state_.last_project);
    active_ = last_workspace;
  } else {
    open_document(context_.examples / "cams" / "roller.xml", true);
  }
  if (options_.workspace) active_ = *options_.workspace;
  if (!workspace(active_)) active_ = workspaces_.front()->kind();
  select_tab_ = active_;
}

App::~App() {
  if (!persist_) return;
  state_.window = window_->placement();
  state_.workspace = active_;
  guarded(log_, "Save the app state", [&] { save_state(state_, state_file_); });
}

Workspace* App::workspace(WorkspaceKind kind) {
  for (auto& w : workspaces_)
    if (w->kind() == kind) return w.get();
  return nullptr;
}

Workspace& App::active() { return *workspace(active_); }

int App::run() {
  if (options_.workspace && !workspace(*options_.workspace)) {
    std::cerr << "polarform-studio: the " << workspace_name(*options_.workspace)
              << " workspace is not part of this build\n";
    return 2;
  }
  if (options_.script) {
    const int status = run_script();
    if (status != 0 || (!options_.screenshot && options_.bench_frames == 0)) return status;
  }
  if (options_.screenshot) return run_screenshot();
  if (options_.bench_frames > 0) return run_bench();
  return run_interactive();
}

void App::frame() {
  compose();
  window_->render();
}

void App::compose() {
  for (auto& w : workspaces_) w->update();
  window_->begin_frame(options_.headless());
  for (const auto& file : window_->take_dropped_files()) open_document(file);
  handle_shortcuts();
  draw_menu_bar();
  draw_main_window();
  handle_dialog();
  draw_shortcuts_window();
  draw_discard_dialog();
  log_panel_.draw_toasts(log_);
  update_title();
}

int App::run_interactive() {
  while (true) {
    if (window_->should_close()) {
      bool dirty = false;
      for (auto& w : workspaces_) dirty |= w->dirty();
      if (!dirty || confirm_quit_) break;
      window_->request_close(false);
      pending_open_.reset();
      ask_discard_ = true;
    }
    frame();
    window_->swap();
  }
  return 0;
}

bool App::settle() {
  const auto start = Clock::now();
  for (int i = 0;; ++i) {
    frame();
    window_->swap();
    bool busy = false;
    for (auto& w : workspaces_) busy |= w->busy();
    if (!busy && i >= 4) return true;
    if (milliseconds_since(start) > 600000.0) return false;
    if (busy) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

bool App::screenshot(const std::filesystem::path& png) {
  frame();
  glFinish();
  const bool written = guarded(log_, "Screenshot", [&] {
    capture_png(png, window_->framebuffer_width(), window_->framebuffer_height());
  });
  window_->swap();
  return written;
}

int App::run_screenshot() {
  if (!settle()) std::cerr << "polarform-studio: computations did not settle within 10 minutes\n";
  const int status = screenshot(*options_.screenshot) ? 0 : 1;
  std::cout << active().numbers();
  std::cout << "errors: " << log_.error_count() << "\n";
  return status;
}

int App::run_bench() {
  settle();
  std::cout << "before:\n" << active().numbers();
  FrameStatistics stats;
  const int frames = options_.bench_frames;
  for (int i = 0; i < frames; ++i) {
    const auto start = Clock::now();
    active().bench_step(i, frames);
    compose();
    const double composed = milliseconds_since(start);
    window_->render();
    glFinish();
    const double rendered = milliseconds_since(start);
    window_->swap();
    const double compute = active().last_compute_ms();
    stats.add({milliseconds_since(start), compute, composed - compute, rendered - composed});
  }
  settle();
  std::cout << "after:\n" << active().numbers();
  std::cout << "workspace: " << workspace_name(active_) << ", window "
            << window_->framebuffer_width() << "x" << window_->framebuffer_height() << "\n";
  std::cout << stats.text();
  std::cout << "errors: " << log_.error_count() << "\n";
  return 0;
}

void App::open_document(const std::filesystem::path& file, bool as_template, Unsaved unsaved) {
  WorkspaceKind kind = WorkspaceKind::cam;
  if (!guarded(log_, "Open " + file.filename().string(), [&] { kind = document_kind(file); }))
    return;
  Workspace* target = workspace(kind);
  if (!target) {
    log_.error("Open " + file.string() + ": the " + std::string(workspace_name(kind)) +
               " workspace is not part of this build");
    return;
  }
  if (unsaved == Unsaved::ask && target->dirty() && !options_.headless()) {
    pending_open_ = PendingOpen{file, as_template, target->document_name()};
    ask_discard_ = true;
    return;
  }
  if (!target->open(file, as_template)) return;
  active_ = kind;
  select_tab_ = kind;
  if (!as_template) state_.remember(file, kind);
}

void App::save(bool choose_path) {
  Workspace& w = active();
  if (!w.can_save()) return;
  if (choose_path || w.document_path().empty()) {
    const auto dir = w.document_path().empty() ? std::filesystem::current_path()
                                               : w.document_path().parent_path();
    const std::string name = w.document_path().empty() ? w.document_name() + ".xml"
                                                       : w.document_path().filename().string();
    purpose_ = DialogPurpose::save_as;
    dialog_.show(FileDialog::Mode::save, "Save project as", {".xml"}, dir, name);
    return;
  }
  if (w.save(w.document_path())) state_.remember(w.document_path(), w.kind());
}

void App::ask_export_path(const ExportRequest& request) {
  pending_export_ = request;
  purpose_ = DialogPurpose::export_file;
  const auto dir = active().document_path().empty() ? std::filesystem::current_path()
                                                    : active().document_path().parent_path();
  dialog_.show(FileDialog::Mode::save, request.title,
               request.extension.empty() ? std::vector<std::string>{}
                                         : std::vector<std::string>{request.extension},
               dir, request.default_name);
}

void App::ask_to_open() {
  purpose_ = DialogPurpose::open;
  const auto dir =
      active().document_path().empty() ? context_.examples : active().document_path().parent_path();
  dialog_.show(FileDialog::Mode::open, "Open project or point cloud", openable_extensions(), dir);
}

void App::handle_dialog() {
  const auto chosen = dialog_.draw();
  if (!chosen) return;
  switch (purpose_) {
    case DialogPurpose::open:
      open_document(*chosen);
      break;
    case DialogPurpose::save_as:
      if (active().save(*chosen)) state_.remember(*chosen, active_);
      break;
    case DialogPurpose::export_file:
      active().export_to(pending_export_, *chosen);
      break;
  }
}

void App::handle_shortcuts() {
  const ImGuiIO& io = ImGui::GetIO();
  const auto pressed = [](int key) { return ImGui::IsKeyPressed(key, false); };
  if (io.KeyCtrl) {
    if (pressed(GLFW_KEY_O)) ask_to_open();
    if (pressed(GLFW_KEY_S)) save(io.KeyShift);
    if (pressed(GLFW_KEY_Q)) window_->request_close(true);
    if (!io.WantTextInput) {
      if (pressed(GLFW_KEY_Z) && !io.KeyShift && active().can_undo()) active().undo();
      if ((pressed(GLFW_KEY_Y) || (pressed(GLFW_KEY_Z) && io.KeyShift)) && active().can_redo())
        active().redo();
    }
    for (int i = 0; i < static_cast<int>(workspaces_.size()) && i < 9; ++i)
      if (pressed(GLFW_KEY_1 + i)) select_tab_ = workspaces_[i]->kind();
  }
  if (pressed(GLFW_KEY_F1)) show_shortcuts_ = !show_shortcuts_;
}

void App::draw_menu_bar() {
  if (!ImGui::BeginMainMenuBar()) return;
  draw_file_menu();
  if (ImGui::BeginMenu("Edit")) {
    if (ImGui::MenuItem("Undo", "Ctrl+Z", false, active().can_undo())) active().undo();
    if (ImGui::MenuItem("Redo", "Ctrl+Y", false, active().can_redo())) active().redo();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    for (int i = 0; i < static_cast<int>(workspaces_.size()); ++i) {
      const std::string shortcut = "Ctrl+" + std::to_string(i + 1);
      const std::string title(workspace_title(workspaces_[i]->kind()));
      if (ImGui::MenuItem(title.c_str(), shortcut.c_str(), active_ == workspaces_[i]->kind()))
        select_tab_ = workspaces_[i]->kind();
    }
    ImGui::Separator();
    if (ImGui::MenuItem("Reset layout")) state_.layout.clear();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    if (ImGui::MenuItem("Keyboard shortcuts", "F1", show_shortcuts_))
      show_shortcuts_ = !show_shortcuts_;
    ImGui::EndMenu();
  }
  // Right side: the document and whether anything is being computed.
  std::string status = active().document_name() + (active().dirty() ? " (modified)" : "");
  if (active().busy()) status = "computing…   " + status;
  ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(status.c_str()).x -
                  ImGui::GetFontSize());
  ImGui::TextDisabled("%s", status.c_str());
  ImGui::EndMainMenuBar();
}

void App::draw_file_menu() {
  if (!ImGui::BeginMenu("File")) return;
  if (ImGui::BeginMenu("New from template")) {
    for (auto& w : workspaces_) {
      if (w->template_folder().empty()) continue;
      ImGui::TextDisabled("%s", std::string(workspace_title(w->kind())).c_str());
      for (const auto& f : list_templates(context_.examples / w->template_folder()))
        if (ImGui::MenuItem(f.stem().string().c_str())) open_document(f, true);
    }
    ImGui::EndMenu();
  }
  if (ImGui::MenuItem("Open…", "Ctrl+O")) ask_to_open();
  if (ImGui::BeginMenu("Open recent", !state_.recent.empty())) {
    for (const auto& f : std::vector<std::filesystem::path>(state_.recent))
      if (ImGui::MenuItem(f.filename().string().c_str(), f.parent_path().string().c_str()))
        open_document(f);
    ImGui::EndMenu();
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Save", "Ctrl+S", false, active().can_save())) save(false);
  if (ImGui::MenuItem("Save as…", "Ctrl+Shift+S", false, active().can_save())) save(true);
  if (ImGui::BeginMenu("Export")) {
    for (const ExportChoice& choice : active().export_choices()) {
      if (choice.separated) ImGui::Separator();
      if (ImGui::MenuItem(choice.label.c_str(), nullptr, false, choice.enabled))
        ask_export_path(choice.request);
      if (!choice.tooltip.empty() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("%s", choice.tooltip.c_str());
    }
    ImGui::EndMenu();
  }
  ImGui::Separator();
  if (ImGui::MenuItem("Quit", "Ctrl+Q")) window_->request_close(true);
  ImGui::EndMenu();
}

void App::draw_main_window() {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(vp->WorkPos);
  ImGui::SetNextWindowSize(vp->WorkSize);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
  // No background: the framebuffer is cleared to the window colour, which saves filling the
  // whole screen once more (software renderers are fill-bound).
  ImGui::Begin("##main", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                   ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoBackground);
  ImGui::PopStyleVar();
  if (ImGui::BeginTabBar("workspaces")) {
    for (auto& w : workspaces_) {
      const std::string title(workspace_title(w->kind()));
      const ImGuiTabItemFlags flags = select_tab_ == w->kind() ? ImGuiTabItemFlags_SetSelected : 0;
      if (ImGui::BeginTabItem(title.c_str(), nullptr, flags)) {
        active_ = w->kind();
        ImGui::EndTabItem();
      }
    }
    select_tab_.reset();
    ImGui::EndTabBar();
  }
  const float height = ImGui::GetContentRegionAvail().y;
  float& log_fraction = state_.layout.try_emplace("log", 0.86f).first->second;
  const float top = split_size(log_fraction, height, ImGui::GetFontSize() * 4);
  ImGui::BeginChild("workspace", ImVec2(0, top), false,
                    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
  active().draw();
  ImGui::EndChild();
  horizontal_splitter("log split", log_fraction, height);
  ImGui::BeginChild("log", ImVec2(0, 0), true);
  log_panel_.draw(log_);
  ImGui::EndChild();
  ImGui::End();
}

void App::draw_shortcuts_window() {
  if (!show_shortcuts_) return;
  ImGui::SetNextWindowSize(ImVec2(ImGui::GetFontSize() * 26, 0), ImGuiCond_Appearing);
  if (ImGui::Begin("Keyboard shortcuts", &show_shortcuts_, ImGuiWindowFlags_NoSavedSettings)) {
    static constexpr const char* kRows[][2] = {
        {"Ctrl+O", "open a project or point cloud"},
        {"Ctrl+S", "save the project"},
        {"Ctrl+Shift+S", "save the project as"},
        {"Ctrl+Z", "undo"},
        {"Ctrl+Y, Ctrl+Shift+Z", "redo"},
        {"Ctrl+1 … Ctrl+4", "switch workspace"},
        {"F1", "this window"},
        {"Ctrl+Q", "quit"},
        {"wheel / drag / double-click", "zoom / pan / fit in plots and views"}};
    if (ImGui::BeginTable("keys", 2, ImGuiTableFlags_RowBg)) {
      for (const auto& row : kRows) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row[0]);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(row[1]);
      }
      ImGui::EndTable();
    }
    ImGui::TextWrapped("Drop a project or point-cloud file on the window to open it.");
  }
  ImGui::End();
}

void App::draw_discard_dialog() {
  if (ask_discard_) ImGui::OpenPopup("Discard changes?");
  ask_discard_ = false;
  if (!ImGui::BeginPopupModal("Discard changes?", nullptr, ImGuiWindowFlags_AlwaysAutoResize))
    return;
  if (pending_open_) {
    ImGui::Text("%s has unsaved changes. Open %s and discard them?",
                pending_open_->document.c_str(), pending_open_->file.filename().string().c_str());
    if (ImGui::Button("Discard and open")) {
      const PendingOpen open = *std::exchange(pending_open_, std::nullopt);
      open_document(open.file, open.as_template, Unsaved::discard);
      ImGui::CloseCurrentPopup();
    }
  } else {
    ImGui::TextUnformatted("A project has unsaved changes. Quit anyway?");
    if (ImGui::Button("Quit without saving")) {
      confirm_quit_ = true;
      window_->request_close(true);
      ImGui::CloseCurrentPopup();
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Cancel")) {
    pending_open_.reset();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void App::update_title() {
  const std::string title =
      "polarform studio — " + active().document_name() + (active().dirty() ? " *" : "");
  if (title != title_) {
    window_->set_title(title);
    title_ = title;
  }
}

}  // namespace polarform::studio
