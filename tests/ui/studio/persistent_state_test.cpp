// Persistent state: the last project, workspace, recent files, window placement and layout
// fractions survive a save and load exactly; a missing file gives the defaults silently; a corrupt
// file is read as far as it makes sense, with one warning and without a crash.
#include "ui/studio/persistent_state.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

namespace polarform::studio {
namespace {

namespace fs = std::filesystem;

class PersistentStateTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("polarform_state_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path file() const { return dir_ / "nested" / "state.ini"; }
  void write(const std::string& text) {
    fs::create_directories(file().parent_path());
    std::ofstream(file(), std::ios::binary) << text;
  }

  fs::path dir_;
  MessageLog log_;
};

TEST_F(PersistentStateTest, RoundTripsEverything) {
  PersistentState state;
  state.remember(dir_ / "a.xml", WorkspaceKind::cam);
  state.remember(dir_ / "scan with spaces.ply", WorkspaceKind::fit);
  state.window = {.x = 40, .y = -12, .width = 1280, .height = 777, .maximized = true};
  state.layout["cam.editor"] = 0.123456789f;  // needs all 9 digits of a float
  state.layout["cam.plots"] = 0.7f;
  state.layout["fit.show_net"] = 1.0f;
  save_state(state, file());

  const PersistentState back = load_state(file(), log_);
  EXPECT_EQ(back.last_project, dir_ / "scan with spaces.ply");
  EXPECT_EQ(back.workspace, WorkspaceKind::fit);
  EXPECT_EQ(back.recent,
            (std::vector<fs::path>{dir_ / "scan with spaces.ply", dir_ / "a.xml"}));
  EXPECT_EQ(back.window.x, 40);
  EXPECT_EQ(back.window.y, -12);
  EXPECT_EQ(back.window.width, 1280);
  EXPECT_EQ(back.window.height, 777);
  EXPECT_TRUE(back.window.maximized);
  EXPECT_EQ(back.layout, state.layout);  // bit-exact floats
  EXPECT_EQ(log_.size(), 0u);
}

TEST_F(PersistentStateTest, RecentListIsNewestFirstWithoutDuplicatesAndBounded) {
  PersistentState state;
  for (int i = 0; i < 15; ++i)
    state.remember(dir_ / ("p" + std::to_string(i) + ".xml"), WorkspaceKind::cam);
  state.remember(dir_ / "p12.xml", WorkspaceKind::vessel);
  ASSERT_EQ(state.recent.size(), PersistentState::kMaxRecent);
  EXPECT_EQ(state.recent[0], dir_ / "p12.xml");
  EXPECT_EQ(state.recent[1], dir_ / "p14.xml");
  EXPECT_EQ(std::count(state.recent.begin(), state.recent.end(), dir_ / "p12.xml"), 1);
  EXPECT_EQ(state.workspace, WorkspaceKind::vessel);
  save_state(state, file());
  EXPECT_EQ(load_state(file(), log_).recent, state.recent);
}

TEST_F(PersistentStateTest, MissingFileGivesDefaultsSilently) {
  const PersistentState state = load_state(dir_ / "none" / "state.ini", log_);
  EXPECT_TRUE(state.last_project.empty());
  EXPECT_EQ(state.workspace, WorkspaceKind::cam);
  EXPECT_EQ(state.window.width, 1600);
  EXPECT_EQ(state.window.height, 1000);
  EXPECT_TRUE(state.layout.empty());
  EXPECT_EQ(log_.size(), 0u);
}

TEST_F(PersistentStateTest, CorruptLinesAreIgnoredWithOneWarning) {
  write("# comment\n"
        "workspace=vessel\n"
        "window.width=abc\n"
        "window.height=90\n"         // below the 240 minimum
        "garbage without equals\n"
        "workspace=spreadsheet\n"
        "layout.cam.editor=0.25\n"
        "layout.cam.plots=0.5x\n"
        "window.x=12\n"
        "unknown_key=3\n");
  const PersistentState state = load_state(file(), log_);
  EXPECT_EQ(state.workspace, WorkspaceKind::vessel);
  EXPECT_EQ(state.window.width, 1600);
  EXPECT_EQ(state.window.height, 1000);
  EXPECT_EQ(state.window.x, 12);
  EXPECT_EQ(state.layout, (std::map<std::string, float>{{"cam.editor", 0.25f}}));
  ASSERT_EQ(log_.size(), 1u);
  const Message m = log_.messages().front();
  EXPECT_EQ(m.severity, Severity::warning);
  EXPECT_THAT(m.text, testing::HasSubstr(file().string()));
  EXPECT_THAT(m.text, testing::HasSubstr("ignored 6 unreadable lines"));
  EXPECT_THAT(m.text, testing::HasSubstr("line 3 'window.width=abc'"));
}

TEST_F(PersistentStateTest, BinaryGarbageGivesDefaultsAndAWarning) {
  std::string noise;
  std::mt19937 random(7);
  for (int i = 0; i < 4096; ++i) noise += static_cast<char>(random() & 0xff);
  write(noise);
  const PersistentState state = load_state(file(), log_);
  EXPECT_TRUE(state.last_project.empty());
  EXPECT_EQ(state.window.width, 1600);
  EXPECT_EQ(log_.size(), 1u);
}

TEST_F(PersistentStateTest, UnreadablePathGivesDefaultsAndAWarning) {
  fs::create_directories(file());  // a directory where the file should be
  const PersistentState state = load_state(file(), log_);
  EXPECT_EQ(state.workspace, WorkspaceKind::cam);
  EXPECT_EQ(log_.size(), 1u);
}

TEST_F(PersistentStateTest, SaveCreatesTheDirectoryAndReplacesTheFile) {
  PersistentState state;
  state.layout["a"] = 0.5f;
  save_state(state, file());
  state.layout.clear();
  state.layout["b"] = 0.75f;
  save_state(state, file());
  EXPECT_EQ(load_state(file(), log_).layout, (std::map<std::string, float>{{"b", 0.75f}}));
}

}  // namespace
}  // namespace polarform::studio
