// The app shell: the window, the workspaces, the menu bar (projects, recent files, templates,
// export, undo/redo, workspaces), keyboard shortcuts, drag-and-drop, the log panel and toasts,
// the persisted state, and the ways to run — interactive, --script (app_script.cpp), --screenshot
// and --bench-frames.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "ui/studio/file_dialog.h"
#include "ui/studio/log_panel.h"
#include "ui/studio/message_log.h"
#include "ui/studio/persistent_state.h"
#include "ui/studio/platform_window.h"
#include "ui/studio/studio_options.h"
#include "ui/studio/studio_script.h"
#include "ui/studio/workspace.h"

namespace polarform::studio {

class App {
 public:
  // Throws std::runtime_error when the window cannot be created.
  explicit App(StudioOptions options);
  ~App();

  // Runs the mode the options ask for; returns the process exit code.
  int run();

 private:
  int run_interactive();
  int run_screenshot();
  int run_bench();
  // Runs --script: exit code 2 for a script that does not parse (nothing runs), 1 when an action
  // failed (the log says why), else 0.
  int run_script();
  void run_action(const ScriptAction& action);
  // Renders the current state and writes it to a PNG; false (logged) when it cannot be written.
  bool screenshot(const std::filesystem::path& png);
  // File ▸ New from template by name, File ▸ Export by tag; failures are logged after `where`.
  void open_template(WorkspaceKind kind, const std::string& name, const std::string& where);
  void export_by_tag(const std::string& tag, const std::filesystem::path& path,
                     const std::string& where);
  // Renders frames until no workspace is busy (at least a few, for ImGui's layout); false on
  // timeout.
  bool settle();
  // One frame: compose() updates the workspaces and builds the UI, then the window renders it.
  void frame();
  void compose();

  void draw_main_window();
  void draw_menu_bar();
  void draw_file_menu();
  void draw_shortcuts_window();
  void draw_discard_dialog();
  void handle_shortcuts();
  void handle_dialog();

  Workspace* workspace(WorkspaceKind kind);
  Workspace& active();
  // Opens a document in its workspace. Over unsaved changes an interactive session asks first
  // (Unsaved::ask); the start-up, a confirmed question and scripts open at once.
  enum class Unsaved { ask, discard };
  void open_document(const std::filesystem::path& file, bool as_template = false,
                     Unsaved unsaved = Unsaved::ask);
  void save(bool choose_path);
  void ask_to_open();
  void ask_export_path(const ExportRequest& request);
  void update_title();

  StudioOptions options_;
  bool persist_;
  std::filesystem::path state_file_;
  MessageLog log_;  // before state_: loading the state may warn
  PersistentState state_;
  StudioContext context_;
  std::unique_ptr<PlatformWindow> window_;
  std::vector<std::unique_ptr<Workspace>> workspaces_;
  WorkspaceKind active_ = WorkspaceKind::cam;
  std::optional<WorkspaceKind> select_tab_;
  LogPanel log_panel_;
  FileDialog dialog_;
  enum class DialogPurpose { open, save_as, export_file } purpose_ = DialogPurpose::open;
  ExportRequest pending_export_;
  bool show_shortcuts_ = false;
  bool confirm_quit_ = false, ask_discard_ = false;
  struct PendingOpen {  // an open waiting for "discard changes?"
    std::filesystem::path file;
    bool as_template = false;
    std::string document;  // the modified one
  };
  std::optional<PendingOpen> pending_open_;
  std::string title_;
};

}  // namespace polarform::studio
