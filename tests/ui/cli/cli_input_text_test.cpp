// Valid input the CLI once refused: file names with non-ASCII letters (rôle.xml, mesure_é.xyz)
// reach IGES, which carries ASCII only, folded to their base letters; bytes that are not UTF-8 in a
// segment name or a grid header reach report.json as U+FFFD instead of ending in a JSON exception.
#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/jobs/cam_job_support.h"
#include "tests/ui/cli/cli_run.h"

namespace polarform {
namespace {

using namespace cam_job_test;

const fs::path kScans = fs::path(POLARFORM_SOURCE_DIR) / "examples" / "scans";

void write_text(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// The IGES file names its source with the accents folded, and every byte of it is printable ASCII
// (or a line end).
void expect_ascii_iges(const fs::path& file, const std::string& folded_name) {
  const std::string iges = slurp(file);
  ASSERT_FALSE(iges.empty()) << file;
  EXPECT_NE(iges.find(folded_name), std::string::npos) << file;
  for (char c : iges) {
    const auto u = static_cast<unsigned char>(c);
    ASSERT_TRUE((u >= 0x20 && u < 0x7F) || c == '\n' || c == '\r') << file << ": byte " << +u;
  }
}

TEST(CliInputText, NonAsciiFileNamesAreValidInput) {
  const ScratchDir scratch("cli_non_ascii");
  const fs::path project = scratch / "rôle.xml";
  fs::copy_file(kExamples / "roller.xml", project);
  const CliRun cam =
      run_cli({"cam", project.string(), "--out", (scratch / "cam").string(), "-q"}, scratch);
  ASSERT_EQ(cam.status, 0) << cam.err;
  expect_ascii_iges(scratch / "cam" / "profile.igs", "role");

  const fs::path scan = scratch / "mesure_é.xyz";
  fs::copy_file(kScans / "vase.xyz", scan);
  const CliRun fit = run_cli(
      {"fit", scan.string(), "--ctrl", "8,8", "--out", (scratch / "fit").string(), "-q"}, scratch);
  ASSERT_EQ(fit.status, 0) << fit.err;
  EXPECT_NE(slurp(scratch / "fit" / "report.json").find("mesure_é.xyz"), std::string::npos);
}

TEST(CliInputText, BytesThatAreNotUtf8ReachTheReportAsReplacementCharacters) {
  const ScratchDir scratch("cli_not_utf8");
  std::string xml = slurp(kExamples / "roller.xml");
  const auto at = xml.find("<segment ");
  ASSERT_NE(at, std::string::npos);
  xml.insert(at + 9,
             "name=\"mont\xE9"
             "e\" ");  // "montée" in Latin-1
  const fs::path project = scratch / "latin1.xml";
  write_text(project, xml);
  const CliRun cam =
      run_cli({"cam", project.string(), "--out", (scratch / "cam").string(), "-q"}, scratch);
  ASSERT_EQ(cam.status, 0) << cam.err;
  EXPECT_NE(slurp(scratch / "cam" / "report.json")
                .find("mont\xEF\xBF\xBD"
                      "e"),
            std::string::npos);

  std::string grid = slurp(kScans / "sphere_grid.csv");
  const auto header = grid.find("pressure_kPa");
  ASSERT_NE(header, std::string::npos);
  grid.replace(header, 8, "pression\xB0");  // "pression°" in Latin-1
  const fs::path grid_file = scratch / "latin1.csv";
  write_text(grid_file, grid);
  const CliRun viz =
      run_cli({"viz", grid_file.string(), "--out", (scratch / "viz").string(), "-q"}, scratch);
  ASSERT_EQ(viz.status, 0) << viz.err;
  EXPECT_NE(slurp(scratch / "viz" / "report.json").find("pression\xEF\xBF\xBD_kPa"),
            std::string::npos);
}

}  // namespace
}  // namespace polarform
