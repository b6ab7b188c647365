// What every workspace (cam, study, vessel, fit) offers the app shell: drawing its panels into
// the main area, collecting background work each frame, its document (open, save, undo/redo),
// its export menu, and the hooks of the headless modes — a scripted edit per benchmark frame and
// the key numbers it reports. Services shared by all workspaces come in a StudioContext.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ui/studio/message_log.h"
#include "ui/studio/workspace_kind.h"

namespace polarform::studio {

class FileDialog;

// Export requests go through the shell's single file dialog: a workspace asks for a path with a
// tag and receives it in export_to().
struct ExportRequest {
  std::string tag;        // the workspace's own name for what to export
  std::string title;      // dialog title
  std::string extension;  // ".igs"; empty: a directory-like name without extension
  std::string default_name;
};

// One item of File ▸ Export: the request it makes, its menu label, whether the results it needs
// exist, and an optional tooltip; `separated` draws a separator above it.
struct ExportChoice {
  ExportRequest request;
  std::string label;
  bool enabled = true;
  std::string tooltip;
  bool separated = false;
};

struct StudioContext {
  MessageLog& log;
  std::map<std::string, float>& layout;  // persisted splitter fractions and toggles
  std::filesystem::path examples;        // examples/ with the templates
  // Opens a file as a new, untitled document in the workspace its kind belongs to (set by the app).
  std::function<void(const std::filesystem::path&)> open_as_template;
};

class Workspace {
 public:
  explicit Workspace(StudioContext& context) : context_(context) {}
  virtual ~Workspace() = default;
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;

  virtual WorkspaceKind kind() const = 0;
  // Once per frame before draw(): recompute after edits, collect finished background work.
  virtual void update() {}
  // Background work still running (headless modes wait for it).
  virtual bool busy() const { return false; }
  // Fills the current window's remaining content region.
  virtual void draw() = 0;

  // The document: a project file (cam, vessel) or a point cloud (fit). open() logs failures and
  // returns false, leaving the current document as it was; a template opens as a new, untitled
  // document. Templates live in examples/<template_folder()>.
  virtual bool accepts(const std::filesystem::path&) const { return false; }
  virtual bool open(const std::filesystem::path&, bool /*as_template*/) { return false; }
  virtual std::string template_folder() const { return {}; }
  virtual bool can_save() const { return false; }
  virtual bool save(const std::filesystem::path&) { return false; }
  virtual std::filesystem::path document_path() const { return {}; }
  virtual std::string document_name() const { return {}; }
  virtual bool dirty() const { return false; }
  virtual bool can_undo() const { return false; }
  virtual bool can_redo() const { return false; }
  virtual void undo() {}
  virtual void redo() {}

  // The items of File ▸ Export (also what `export TAG PATH` of a --script can name); a chosen
  // item's path arrives in export_to().
  virtual std::vector<ExportChoice> export_choices() const { return {}; }
  virtual void export_to(const ExportRequest&, const std::filesystem::path&) {}

  // Headless modes: the scripted edit of benchmark frame `frame` of `frames`, the design edit of
  // a script's `edit` (false: the workspace has none), and the key numbers as "name=value" lines.
  virtual void bench_step(int, int) {}
  virtual bool scripted_edit() { return false; }
  virtual std::string numbers() const { return {}; }
  // Milliseconds spent recomputing in the last update().
  virtual double last_compute_ms() const { return 0.0; }

 protected:
  MessageLog& log() { return context_.log; }
  float& layout(const std::string& key, float fallback) {
    return context_.layout.try_emplace(key, fallback).first->second;
  }

  StudioContext& context_;
};

}  // namespace polarform::studio
