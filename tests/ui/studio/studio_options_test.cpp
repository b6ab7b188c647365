// Command-line options of polarform-studio: the defaults, every option read back, and bad values
// of --size, --workspace, --bench-frames, --project and --script refused with exit code 2 and a
// message naming the option.
#include "ui/studio/studio_options.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace polarform::studio {
namespace {

struct Parsed {
  std::optional<StudioOptions> options;
  int exit_code = -1;
  std::string errors;  // stderr
};

Parsed parse(std::vector<std::string> args) {
  args.insert(args.begin(), "polarform-studio");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  Parsed p;
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  p.options = parse_options(static_cast<int>(argv.size()), argv.data(), p.exit_code);
  testing::internal::GetCapturedStdout();
  p.errors = testing::internal::GetCapturedStderr();
  return p;
}

const std::string kRoller = std::string(POLARFORM_SOURCE_DIR) + "/examples/cams/roller.xml";

TEST(StudioOptions, Defaults) {
  const Parsed p = parse({});
  ASSERT_TRUE(p.options);
  EXPECT_EQ(p.exit_code, 0);
  EXPECT_FALSE(p.options->project);
  EXPECT_FALSE(p.options->workspace);
  EXPECT_FALSE(p.options->headless());
  EXPECT_EQ(p.options->width, 1600);
  EXPECT_EQ(p.options->height, 1000);
  EXPECT_FALSE(p.options->size_given);
}

TEST(StudioOptions, ReadsEveryOption) {
  const Parsed p = parse({"--project", kRoller, "--workspace", "vessel", "--screenshot", "out.png",
                          "--bench-frames", "300", "--size", "800x600"});
  ASSERT_TRUE(p.options) << p.errors;
  EXPECT_EQ(p.options->project, kRoller);
  EXPECT_EQ(p.options->workspace, WorkspaceKind::vessel);
  EXPECT_EQ(p.options->screenshot, "out.png");
  EXPECT_EQ(p.options->bench_frames, 300);
  EXPECT_EQ(p.options->width, 800);
  EXPECT_EQ(p.options->height, 600);
  EXPECT_TRUE(p.options->size_given);
  EXPECT_TRUE(p.options->headless());
}

TEST(StudioOptions, ScriptAndStateDirectory) {
  // A script alone is headless; the state folder need not exist yet (the app creates it).
  const Parsed p = parse({"--script", kRoller, "--state-dir", "/tmp/polarform-state-not-yet"});
  ASSERT_TRUE(p.options) << p.errors;
  EXPECT_EQ(p.options->script, kRoller);
  EXPECT_EQ(p.options->state_dir, "/tmp/polarform-state-not-yet");
  EXPECT_TRUE(p.options->headless());
  EXPECT_FALSE(p.options->screenshot);
  const Parsed missing = parse({"--script", "/no/such/script.txt"});
  EXPECT_FALSE(missing.options);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_THAT(missing.errors, testing::HasSubstr("/no/such/script.txt"));
}

TEST(StudioOptions, AcceptsTheSizeLimits) {
  for (const char* size : {"320x240", "16384x16384"}) {
    const Parsed p = parse({"--size", size});
    EXPECT_TRUE(p.options) << size << ": " << p.errors;
  }
}

TEST(StudioOptions, RefusesMalformedSizes) {
  for (const char* size : {"1600", "1600x", "x1000", "1600X1000", "1600*1000",
                           "1600x1000x3", " 1600x1000", "big", "1e3x1e3"}) {
    const Parsed p = parse({"--size", size});
    EXPECT_FALSE(p.options) << size;
    EXPECT_EQ(p.exit_code, 2) << size;
    EXPECT_THAT(p.errors, testing::HasSubstr("--size: expected WIDTHxHEIGHT")) << size;
  }
}

TEST(StudioOptions, RefusesSizesOutOfRange) {
  for (const char* size : {"319x1000", "1600x239", "10x10", "16385x1000", "99999x99999"}) {
    const Parsed p = parse({"--size", size});
    EXPECT_FALSE(p.options) << size;
    EXPECT_EQ(p.exit_code, 2) << size;
    EXPECT_THAT(p.errors, testing::HasSubstr("--size: from 320x240 to 16384x16384, got " +
                                             std::string(size)));
  }
}

TEST(StudioOptions, RefusesUnknownWorkspaces) {
  for (const char* workspace : {"cams", "Cam", "designer"}) {
    const Parsed p = parse({"--workspace", workspace});
    EXPECT_FALSE(p.options) << workspace;
    EXPECT_EQ(p.exit_code, 2) << workspace;
    EXPECT_THAT(p.errors, testing::HasSubstr("--workspace")) << workspace;
  }
  for (const char* workspace : {"cam", "study", "vessel", "fit"}) {
    const Parsed p = parse({"--workspace", workspace});
    ASSERT_TRUE(p.options) << workspace << ": " << p.errors;
    EXPECT_EQ(workspace_name(*p.options->workspace), workspace);
  }
}

TEST(StudioOptions, RefusesBadFrameCountsAndMissingProjects) {
  for (const char* frames : {"0", "-3", "many"}) {
    const Parsed p = parse({"--bench-frames", frames});
    EXPECT_FALSE(p.options) << frames;
    EXPECT_EQ(p.exit_code, 2);
    EXPECT_THAT(p.errors, testing::HasSubstr("--bench-frames")) << frames;
  }
  const Parsed p = parse({"--project", "/no/such/project.xml"});
  EXPECT_FALSE(p.options);
  EXPECT_EQ(p.exit_code, 2);
  EXPECT_THAT(p.errors, testing::HasSubstr("/no/such/project.xml"));
}

TEST(StudioOptions, HelpExitsWithZero) {
  const Parsed p = parse({"--help"});
  EXPECT_FALSE(p.options);
  EXPECT_EQ(p.exit_code, 0);
}

}  // namespace
}  // namespace polarform::studio
