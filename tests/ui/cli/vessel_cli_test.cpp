// `polarform vessel` as a user runs it: exit code 0 and every file for a good project, 2 and one
// line naming file:line:attribute for a bad one (with nothing written), 1 with the numbers for a
// synthesis that does not converge; --tol overrides the project's tolerance; no tolerance below
// the converter's floor anywhere.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "jobs/vessel/vessel_job.h"
#include "src/error.h"
#include "tests/support/jobs/vessel_job_support.h"

namespace polarform {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;
using namespace vessel_job_test;

struct CliRun {
  int exit_code = -1;
  std::string out, err;
};

CliRun polarform(const std::string& args) {
  const std::filesystem::path dir = scratch_dir("cli");
  const std::string command = std::string(POLARFORM_BINARY_DIR) + "/ui/cli/polarform " + args +
                              " >" + (dir / "out.txt").string() +
                              " 2>" + (dir / "err.txt").string();
  const int status = std::system(command.c_str());
  CliRun r;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  r.out = read_text(dir / "out.txt");
  r.err = read_text(dir / "err.txt");
  return r;
}

TEST(VesselCli, GoodProjectExitsZeroAndWritesEverything) {
  const std::filesystem::path out = scratch_dir("out");
  const CliRun r = polarform("vessel " + example("torispherical_100_6.xml").string() + " --out " +
                          out.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("synthesis: 180 targets, "));
  EXPECT_THAT(r.out, HasSubstr("tolerance 0.001 mm: measured max radial error "));
  EXPECT_THAT(r.out, HasSubstr("wrote 13 files to " + out.string()));
  EXPECT_EQ(files_in(out).size(), 13u);
}

TEST(VesselCli, TolOverridesTheProjectAndQuietPrintsNothing) {
  const std::filesystem::path out = scratch_dir("out");
  const CliRun r = polarform("vessel " + example("custom_curvature.xml").string() + " --out " +
                          out.string() + " --tol 1e-5 --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  const auto j = nlohmann::json::parse(read_text(out / "report.json"));
  EXPECT_EQ(j["tolerance_mm"], 1e-5);
  EXPECT_LE(j["max_radial_error_mm"].get<double>(), 1e-5);
}

TEST(VesselCli, BadFileExitsTwoNamingTheLineAndWritesNothing) {
  const std::filesystem::path out = scratch_dir("out");
  const std::filesystem::path bad = write_text(
      scratch_dir("in") / "bad.xml",
      "<?xml version=\"1.0\"?>\n<polarform version=\"1\">\n"
      "<vessel radius=\"-500\" length=\"1500\" thickness=\"10\" pressure=\"2\">\n"
      "<head preset=\"hemispherical\"/></vessel></polarform>\n");
  const CliRun r = polarform("vessel " + bad.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "polarform: error: " + bad.string() +
                       ":3: <vessel> attribute 'radius': expected a number > 0, got '-500'\n");
  EXPECT_TRUE(files_in(out).empty());
  EXPECT_EQ(polarform("vessel /nonexistent/design.xml --out " + out.string()).exit_code, 2);
  EXPECT_EQ(polarform("vessel " + bad.string()).exit_code, 2);  // --out is required
}

// The converter's floor (kMinTolerance, 1e-9 mm) holds for vessels as for cams: in the file, on
// the command line and in the job itself.
TEST(VesselCli, ToleranceBelowTheFloorExitsTwoAndWritesNothing) {
  const std::filesystem::path out = scratch_dir("out");
  const std::filesystem::path tight = write_text(
      scratch_dir("in") / "tight.xml",
      "<?xml version=\"1.0\"?>\n<polarform version=\"1\">\n"
      "<vessel radius=\"500\" length=\"1500\" thickness=\"10\" pressure=\"2\">\n"
      "<head preset=\"hemispherical\"/></vessel>\n<conversion tolerance=\"1e-12\"/>\n"
      "</polarform>\n");
  const CliRun file = polarform("vessel " + tight.string() + " --out " + out.string());
  EXPECT_EQ(file.exit_code, 2);
  EXPECT_EQ(file.err, "polarform: error: " + tight.string() +
                          ":5: <conversion> attribute 'tolerance': expected a tolerance >= 1e-09 "
                          "mm, got '1e-12'\n");
  const CliRun flag = polarform("vessel " + example("hemispherical.xml").string() + " --out " +
                                out.string() + " --tol 1e-10");
  EXPECT_EQ(flag.exit_code, 2);
  EXPECT_THAT(flag.err, HasSubstr("--tol"));
  EXPECT_THAT(flag.err, HasSubstr("expected a tolerance >= 1e-09 mm"));
  EXPECT_TRUE(files_in(out).empty());
  VesselProject project = load_example("hemispherical.xml");
  project.tolerance = 5e-10;
  EXPECT_THROW(run_vessel_job(project), InputError);
}

TEST(VesselCli, InfeasibleDesignExitsTwoNamingTheFileAndTheNumbers) {
  const std::filesystem::path out = scratch_dir("out");
  const std::filesystem::path design =
      write_text(scratch_dir("in") / "contradictory.xml", contradictory_project());
  const CliRun r = polarform("vessel " + design.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, StartsWith("polarform: error: " + design.string() +
                                ": synthesis: contradictory end conditions: R(π) = 480 mm"));
  EXPECT_TRUE(files_in(out).empty());
}

TEST(VesselCli, NonConvergenceExitsOneWithTheNumbers) {
  const std::filesystem::path out = scratch_dir("out");
  const std::filesystem::path design =
      write_text(scratch_dir("in") / "stuck.xml", non_converging_project());
  const CliRun r = polarform("vessel " + design.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, StartsWith("polarform: error: " + design.string() +
                                ": synthesis: SLSQP did not converge within 2 evaluations"));
  EXPECT_TRUE(files_in(out).empty());
}

TEST(VesselCli, HelpDescribesTheCommand) {
  const CliRun r = polarform("vessel --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* text : {"--out", "--tol", "--quiet", "report.json", "vessel.stp"})
    EXPECT_THAT(r.out, HasSubstr(text)) << text;
}

}  // namespace
}  // namespace polarform
