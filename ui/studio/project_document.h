// An open project: the live value the panels edit, the file it belongs to (none for a new one
// from a template), whether it differs from what was last saved or opened, and its undo history
// (one step per finished edit, see UndoHistory).
#pragma once

#include <filesystem>
#include <string>
#include <utility>

#include "ui/studio/undo_history.h"

namespace polarform::studio {

template <class Project>
class ProjectDocument {
 public:
  // The live value; edits become undo steps when settle() sees no widget editing.
  Project& edit() { return current_; }
  const Project& current() const { return current_; }

  // A newly opened (path set) or created (path empty, named `name`) project: no history.
  void replace(Project project, std::filesystem::path path, std::string name) {
    current_ = std::move(project);
    saved_ = current_;
    history_.reset(current_);
    path_ = std::move(path);
    name_ = std::move(name);
  }
  void settle(bool editing) { history_.settle(current_, editing); }
  bool can_undo() const { return history_.can_undo(current_); }
  bool can_redo() const { return history_.can_redo(); }
  void undo() { current_ = history_.undo(current_); }
  void redo() { current_ = history_.redo(current_); }

  const std::filesystem::path& path() const { return path_; }
  std::string name() const { return path_.empty() ? name_ : path_.filename().string(); }
  bool dirty() const { return !(current_ == saved_); }
  void saved_as(std::filesystem::path path) {
    path_ = std::move(path);
    saved_ = current_;
  }

 private:
  Project current_{}, saved_{};
  UndoHistory<Project> history_;
  std::filesystem::path path_;
  std::string name_ = "untitled";
};

}  // namespace polarform::studio
