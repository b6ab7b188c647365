// Undo/redo of every design edit by snapshots of the whole (small) design value. Continuous
// edits — dragging a slider, typing a number — become one step: the live value is committed only
// when no widget is being edited and it differs from the last committed one.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace polarform::studio {

template <class T>
class UndoHistory {
 public:
  explicit UndoHistory(T initial = {}) : committed_(std::move(initial)) {}

  // Once per frame with the live value; `editing` while a widget still holds an edit.
  void settle(const T& current, bool editing) {
    if (!editing && !(current == committed_)) commit(current);
  }
  bool can_undo(const T& current) const { return !undo_.empty() || !(current == committed_); }
  bool can_redo() const { return !redo_.empty(); }

  // The value to restore; `current` may hold an edit not yet committed, which is committed first.
  T undo(const T& current) {
    if (!(current == committed_)) commit(current);
    if (undo_.empty()) return committed_;
    redo_.push_back(std::move(committed_));
    committed_ = std::move(undo_.back());
    undo_.pop_back();
    return committed_;
  }
  T redo(const T& current) {
    if (!(current == committed_)) commit(current);  // an edit after undo drops the redo branch
    if (redo_.empty()) return committed_;
    undo_.push_back(std::move(committed_));
    committed_ = std::move(redo_.back());
    redo_.pop_back();
    return committed_;
  }
  // A new document: no history.
  void reset(T value) {
    undo_.clear();
    redo_.clear();
    committed_ = std::move(value);
  }

 private:
  static constexpr std::size_t kLimit = 500;

  void commit(const T& current) {
    undo_.push_back(std::move(committed_));
    if (undo_.size() > kLimit) undo_.erase(undo_.begin());
    committed_ = current;
    redo_.clear();
  }

  std::vector<T> undo_, redo_;
  T committed_;
};

}  // namespace polarform::studio
