// The CLI on inputs that ask for too much or make no sense: sizes beyond the documented limits are
// refused before anything is allocated (exit 2, the option and the limit named), degenerate data
// is refused with the file's name, and no output directory is created.
#include <gtest/gtest.h>

#include <fstream>
#include <numbers>
#include <random>

#include "tests/support/jobs/cam_job_support.h"
#include "tests/ui/cli/cli_run.h"

namespace polarform {
namespace {

using namespace cam_job_test;

const fs::path kScans = fs::path(POLARFORM_SOURCE_DIR) / "examples" / "scans";

// Runs the CLI and expects exit 2, every fragment in the one-line message, and no output.
void expect_refused(const std::vector<std::string>& args, const ScratchDir& scratch,
                    const std::vector<std::string>& fragments) {
  fs::remove_all(scratch / "out");
  std::vector<std::string> all = args;
  all.insert(all.end(), {"--out", (scratch / "out").string(), "-q"});
  const CliRun run = run_cli(all, scratch);
  EXPECT_EQ(run.status, 2) << args[0] << " " << args[1] << ": " << run.err;
  for (const std::string& f : fragments)
    EXPECT_NE(run.err.find(f), std::string::npos) << "'" << f << "' not in: " << run.err;
  EXPECT_FALSE(fs::exists(scratch / "out")) << args[1];
}

TEST(CliInputLimits, ControlNetsBeyondTheLimitAreRefusedByName) {
  const ScratchDir scratch("cli_limits_ctrl");
  expect_refused({"fit", (kScans / "vase.xyz").string(), "--ctrl", "2000,2000"}, scratch,
                 {"--ctrl 2000 x 2000", "4000000 coefficients", "65536"});
  expect_refused({"viz", (kScans / "sphere_grid.csv").string(), "--ctrl", "300,300"}, scratch,
                 {"--ctrl 300 x 300", "90000 coefficients", "65536"});
}

// Degenerate clouds: every message names the file and what is wrong with its points.
TEST(CliInputLimits, DegenerateCloudsAreRefusedNamingTheFile) {
  const ScratchDir scratch("cli_limits_degenerate");
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::string identical, collinear, disc, sphere;
  for (int k = 0; k < 100; ++k) {
    identical += "1 2 3\n";
    collinear +=
        std::to_string(k) + " " + std::to_string(2 * k) + " " + std::to_string(3 * k) + "\n";
  }
  for (int k = 0; k < 2000; ++k) {
    const double r = 10 * std::sqrt(U(rng)), t = 2 * std::numbers::pi * U(rng);
    disc += std::to_string(r * std::cos(t)) + " " + std::to_string(r * std::sin(t)) + " 0\n";
  }
  for (int k = 0; k < 2000; ++k) {
    const double z = 2 * U(rng) - 1, t = 2 * std::numbers::pi * U(rng), s = std::sqrt(1 - z * z);
    sphere += std::to_string(20 * s * std::cos(t)) + " " + std::to_string(20 * s * std::sin(t)) +
              " " + std::to_string(20 * z) + "\n";
  }
  const std::vector<std::pair<std::string, std::string>> clouds = {
      {"sphere.xyz", sphere},
      {"identical.xyz", identical},
      {"three.xyz", "0 0 0\n1 0 0\n0 1 0\n"},
      {"collinear.xyz", collinear},
      {"disc.xyz", disc}};
  for (const auto& [name, text] : clouds) std::ofstream(scratch / name) << text;
  const auto file = [&](const std::string& name) { return (scratch / name).string(); };
  expect_refused({"fit", file("identical.xyz")}, scratch,
                 {file("identical.xyz") + ": ", "all points coincide"});
  expect_refused({"fit", file("three.xyz")}, scratch, {file("three.xyz") + ": ", "3 points"});
  expect_refused({"fit", file("collinear.xyz")}, scratch,
                 {file("collinear.xyz") + ": ", "straight line"});
  expect_refused({"fit", file("collinear.xyz"), "--method", "cylindrical"}, scratch,
                 {file("collinear.xyz") + ": cylindrical fit: the points lie on a straight line"});
  expect_refused({"fit", file("disc.xyz")}, scratch,
                 {file("disc.xyz") + ": polar curve fit: the points fill a region",
                  "% of the typical radius"});
  expect_refused({"scan-cam", file("disc.xyz")}, scratch, {file("disc.xyz") + ": "});
  expect_refused({"scan-cam", file("sphere.xyz"), "--center", "0,0,0"}, scratch,
                 {file("sphere.xyz") + ": cam scan: a 3D scan whose faces are not flat"});
  expect_refused({"scan-cam", file("identical.xyz"), "--center", "0,0,0"}, scratch,
                 {file("identical.xyz") + ": cam scan: all points coincide"});
}

// A centre of rotation far outside the cam: seen from it the contour is a narrow sector.
TEST(CliInputLimits, ACentreOutsideTheCamIsRefused) {
  const ScratchDir scratch("cli_limits_centre");
  const std::string scan = (kScans / "cam_profile.xyz").string();
  expect_refused({"scan-cam", scan, "--center", "1000000,0"}, scratch,
                 {scan + ": cam scan: the contour does not surround the centre of rotation",
                  "check --center"});
  // The bundled scan about its bore is accepted: the check does not refuse a whole contour.
  const CliRun good =
      run_cli({"scan-cam", scan, "--out", (scratch / "good").string(), "-q"}, scratch);
  EXPECT_EQ(good.status, 0) << good.err;
}

TEST(CliInputLimits, AGridOnOneMeridianIsRefusedNamingTheFile) {
  const ScratchDir scratch("cli_limits_grid");
  std::string grid = "p,phi_deg,theta_deg\n";
  for (int k = 0; k <= 18; ++k)
    grid += std::to_string(1 + 0.01 * k) + "," + std::to_string(10 * k) + ",0\n";
  std::ofstream(scratch / "meridian.csv") << grid;
  expect_refused({"viz", (scratch / "meridian.csv").string()}, scratch,
                 {(scratch / "meridian.csv").string() + ": every row has theta_deg = 0",
                  "at least two distinct theta_deg values"});
}

TEST(CliInputLimits, AMissingOrUnknownCommandListsTheCommands) {
  const ScratchDir scratch("cli_limits_command");
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"frobnicate", "x.xml"}, std::vector<std::string>{}}) {
    const CliRun run = run_cli(args, scratch);
    EXPECT_EQ(run.status, 2);
    EXPECT_NE(run.err.find(args.empty() ? "no command given" : "unknown command 'frobnicate'"),
              std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("the commands are cam, "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("scan-cam"), std::string::npos) << run.err;
  }
}

// An --out that is a file, or a folder that cannot be made (under /proc, which even root cannot
// write), stops every command with exit 2 before anything is written; the file stays as it was.
TEST(CliInputLimits, AnOutputThatIsAFileOrUnwritableLosesNothing) {
  const ScratchDir scratch("cli_limits_out");
  const fs::path vessels = fs::path(POLARFORM_SOURCE_DIR) / "examples" / "vessels";
  const std::vector<std::vector<std::string>> commands = {
      {"cam", (kExamples / "roller.xml").string()},
      {"study", (kExamples / "roller.xml").string(), "--no-peers"},  // the peers take seconds
      {"vessel", (vessels / "hemispherical.xml").string()},
      {"fit", (kScans / "vase.xyz").string()},
      {"scan-cam", (kScans / "cam_profile.xyz").string()},
      {"viz", (kScans / "sphere_grid.csv").string()}};
  const fs::path file = scratch / "report.txt";
  std::ofstream(file) << "an earlier file\n";
  for (const auto& command : commands)
    for (const fs::path& out : {file, file / "sub", fs::path("/proc/polarform_out")}) {
      std::vector<std::string> args = command;
      args.insert(args.end(), {"--out", out.string(), "-q"});
      const CliRun run = run_cli(args, scratch);
      EXPECT_EQ(run.status, 2) << command[0] << " " << out;
      EXPECT_NE(run.err.find(out.string() + ": cannot create the output directory"),
                std::string::npos)
          << run.err;
      EXPECT_EQ(slurp(file), "an earlier file\n");
    }
}

}  // namespace
}  // namespace polarform
