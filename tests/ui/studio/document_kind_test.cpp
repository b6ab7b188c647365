// Document kind: project XML goes to the cam, vessel or fit workspace by its root element, scans to
// the fit workspace by extension (any case); unknown types, broken XML and XML holding neither
// design are refused with InputError naming the file.
#include "ui/studio/document_kind.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include "src/error.h"

namespace polarform::studio {
namespace {

namespace fs = std::filesystem;

const fs::path kExamples = fs::path(POLARFORM_SOURCE_DIR) / "examples";

class DocumentKindTest : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("polarform_kind_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  void expect_refused(const fs::path& file, const char* words) {
    try {
      document_kind(file);
      ADD_FAILURE() << file << " was accepted";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), testing::HasSubstr(file.string()));
      EXPECT_THAT(e.what(), testing::HasSubstr(words));
    }
  }

  fs::path dir_;
};

TEST_F(DocumentKindTest, ExampleProjects) {
  EXPECT_EQ(document_kind(kExamples / "cams" / "roller.xml"), WorkspaceKind::cam);
  EXPECT_EQ(document_kind(kExamples / "vessels" / "ellipsoidal_2_1.xml"), WorkspaceKind::vessel);
  EXPECT_EQ(document_kind(kExamples / "scans" / "sphere_like_fit.xml"), WorkspaceKind::fit);
}

TEST_F(DocumentKindTest, BareAndWrappedRootElements) {
  EXPECT_EQ(document_kind(write("a.xml", "<cam/>")), WorkspaceKind::cam);
  EXPECT_EQ(document_kind(write("b.XML", "<polarform><cam/></polarform>")), WorkspaceKind::cam);
  EXPECT_EQ(document_kind(write("c.xml", "<vessel/>")), WorkspaceKind::vessel);
  EXPECT_EQ(document_kind(write("d.xml", "<polarform><vessel/></polarform>")),
            WorkspaceKind::vessel);
  EXPECT_EQ(document_kind(write("e.xml", "<fit scan=\"s.ply\"/>")), WorkspaceKind::fit);
  EXPECT_EQ(document_kind(write("f.xml", "<polarform><fit/></polarform>")), WorkspaceKind::fit);
}

TEST_F(DocumentKindTest, ScansGoToTheFitWorkspaceWithoutBeingRead) {
  for (const char* name : {"s.xyz", "s.csv", "s.txt", "s.pts", "s.ply", "s.STL", "s.Obj", "s.off"})
    EXPECT_EQ(document_kind(dir_ / name), WorkspaceKind::fit) << name;
}

TEST_F(DocumentKindTest, RefusesWhatNoWorkspaceReads) {
  expect_refused(dir_ / "drawing.dwg", "unknown file type '.dwg'");
  expect_refused(dir_ / "no_extension", "unknown file type ''");
  expect_refused(write("broken.xml", "<cam><segments></cam"), "");
  expect_refused(write("other.xml", "<polarform><pump/></polarform>"),
                 "neither a cam, a vessel nor a fit project");
  expect_refused(write("empty.xml", ""), "");
}

TEST_F(DocumentKindTest, OpenableExtensionsCoverProjectsAndScans) {
  const auto& e = openable_extensions();
  EXPECT_EQ(e.front(), ".xml");
  for (const auto& ext : e)
    EXPECT_NO_THROW(
        ext == ".xml" ? document_kind(kExamples / "cams" / "roller.xml") : document_kind("x" + ext))
        << ext;
}

}  // namespace
}  // namespace polarform::studio
