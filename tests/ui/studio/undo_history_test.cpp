// UndoHistory: undo and redo restore the exact committed states in order, a continuous edit
// (editing == true) is one step, an edit after undo cuts the redo branch, reset forgets all.
#include "ui/studio/undo_history.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace polarform::studio {
namespace {

TEST(UndoHistory, UndoAndRedoRestoreExactStatesInOrder) {
  UndoHistory<std::vector<double>> history({1.0});
  std::vector<double> v = {1.0};
  for (double x : {2.5, 3.25, 4.125}) {
    v.push_back(x);
    history.settle(v, false);
  }
  ASSERT_EQ(v, (std::vector<double>{1.0, 2.5, 3.25, 4.125}));
  EXPECT_TRUE(history.can_undo(v));
  EXPECT_FALSE(history.can_redo());

  v = history.undo(v);
  EXPECT_EQ(v, (std::vector<double>{1.0, 2.5, 3.25}));
  v = history.undo(v);
  EXPECT_EQ(v, (std::vector<double>{1.0, 2.5}));
  v = history.undo(v);
  EXPECT_EQ(v, (std::vector<double>{1.0}));
  EXPECT_FALSE(history.can_undo(v));
  v = history.undo(v);  // nothing left: stays at the first state
  EXPECT_EQ(v, (std::vector<double>{1.0}));

  v = history.redo(v);
  EXPECT_EQ(v, (std::vector<double>{1.0, 2.5}));
  v = history.redo(v);
  v = history.redo(v);
  EXPECT_EQ(v, (std::vector<double>{1.0, 2.5, 3.25, 4.125}));
  EXPECT_FALSE(history.can_redo());
  v = history.redo(v);
  EXPECT_EQ(v, (std::vector<double>{1.0, 2.5, 3.25, 4.125}));
}

TEST(UndoHistory, ContinuousEditIsOneStep) {
  UndoHistory<int> history(0);
  int value = 0;
  for (int drag = 1; drag <= 50; ++drag) {
    value = drag;
    history.settle(value, true);  // the slider is still held
  }
  history.settle(value, false);  // released
  EXPECT_EQ(history.undo(value), 0);
  EXPECT_EQ(history.redo(0), 50);
}

TEST(UndoHistory, SettlingAnUnchangedValueAddsNoStep) {
  UndoHistory<int> history(7);
  for (int i = 0; i < 10; ++i) history.settle(7, false);
  EXPECT_FALSE(history.can_undo(7));
}

TEST(UndoHistory, NewEditCutsTheRedoBranch) {
  UndoHistory<std::string> history("a");
  std::string s = "a";
  for (const char* next : {"ab", "abc"}) {
    s = next;
    history.settle(s, false);
  }
  s = history.undo(s);
  ASSERT_EQ(s, "ab");
  ASSERT_TRUE(history.can_redo());
  s = "abX";  // an edit on the undone state
  history.settle(s, false);
  EXPECT_FALSE(history.can_redo());
  EXPECT_EQ(history.redo(s), "abX");  // "abc" is gone
  EXPECT_EQ(history.undo(s), "ab");
  EXPECT_EQ(history.undo("ab"), "a");
}

TEST(UndoHistory, UndoCommitsAPendingEditFirst) {
  UndoHistory<int> history(1);
  // An edit not yet settled (the widget is still active) is undone as its own step...
  EXPECT_EQ(history.undo(2), 1);
  // ...and can be redone exactly.
  EXPECT_TRUE(history.can_redo());
  EXPECT_EQ(history.redo(1), 2);
}

TEST(UndoHistory, RedoAfterAPendingEditDropsTheBranch) {
  UndoHistory<int> history(1);
  history.settle(2, false);
  ASSERT_EQ(history.undo(2), 1);
  EXPECT_EQ(history.redo(5), 5);  // the pending edit 5 wins over the redo branch
  EXPECT_FALSE(history.can_redo());
  EXPECT_EQ(history.undo(5), 1);
}

TEST(UndoHistory, KeepsTheNewest500Steps) {
  UndoHistory<int> history(0);
  for (int i = 1; i <= 600; ++i) history.settle(i, false);
  int v = 600, steps = 0;
  while (history.can_undo(v)) {
    v = history.undo(v);
    ++steps;
  }
  EXPECT_EQ(steps, 500);
  EXPECT_EQ(v, 100);
}

TEST(UndoHistory, ResetForgetsTheHistory) {
  UndoHistory<int> history(0);
  history.settle(1, false);
  history.settle(2, false);
  history.undo(2);
  history.reset(9);
  EXPECT_FALSE(history.can_undo(9));
  EXPECT_FALSE(history.can_redo());
  EXPECT_EQ(history.undo(9), 9);
}

}  // namespace
}  // namespace polarform::studio
