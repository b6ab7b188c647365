// `polarform pipe` as a user runs it: a pipe around a bent spine (exit 0), a radius beyond the
// self-intersection bound (exit 2, one line naming δ and the mode, nothing written; with
// --allow-self-intersection the files and a warning), a bad spine file (exit 2, its line), and a
// <pipe> project: its radius taken unless --radius overrides it, a bad value exit 2 by line.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "tests/support/jobs/cam_job_support.h"
#include "tests/ui/cli/cli_run.h"

namespace polarform {
namespace {

using namespace cam_job_test;

// A quarter circle of radius 10 in the xy-plane, then straight on along y.
void write_spine(const ScratchDir& dir) {
  std::ofstream out(dir / "spine.csv");
  out.precision(17);
  out << "x,y,z\n";
  for (int k = 0; k <= 30; ++k) {
    const double a = 1.5707963267948966 * k / 30;
    out << 10 * std::cos(a) - 10 << ',' << 10 * std::sin(a) << ",0\n";
  }
}

TEST(PipeCli, BuildsAPipe) {
  const ScratchDir dir("pipe_cli_ok");
  write_spine(dir);
  const CliRun run = run_cli({"pipe", (dir / "spine.csv").string(), "--radius", "2", "--out",
                              (dir / "out").string()},
                             dir);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("radius bound δ"), std::string::npos) << run.out;
  EXPECT_TRUE(fs::exists(dir / "out" / "pipe.stp"));
  EXPECT_TRUE(fs::exists(dir / "out" / "curvature.svg"));
}

TEST(PipeCli, ARadiusBeyondTheBoundIsRefused) {
  const ScratchDir dir("pipe_cli_bad");
  write_spine(dir);
  const std::vector<std::string> base = {"pipe", (dir / "spine.csv").string(), "--radius", "12",
                                         "--out", (dir / "out").string()};
  const CliRun run = run_cli(base, dir);
  EXPECT_EQ(run.status, 2) << run.err;
  EXPECT_NE(run.err.find("the pipe self-intersects for radii at or beyond δ = "),
            std::string::npos)
      << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
  std::vector<std::string> allowed = base;
  allowed.push_back("--allow-self-intersection");
  const CliRun forced = run_cli(allowed, dir);
  EXPECT_EQ(forced.status, 0) << forced.err;
  EXPECT_NE(forced.err.find("polarform: warning:"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "out" / "pipe.igs"));
}

TEST(PipeCli, ABadSpineFileNamesTheLine) {
  const ScratchDir dir("pipe_cli_file");
  {
    std::ofstream out(dir / "bad.csv");
    out << "x,y,z\n0,0,0\n1,x,0\n";
  }
  const CliRun run = run_cli({"pipe", (dir / "bad.csv").string(), "--radius", "1", "--out",
                              (dir / "out").string()},
                             dir);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("bad.csv:3: y 'x': expected a finite number"), std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// The quarter circle of radius 10 as a rational quadratic (weight cos 45°), radius 2 in the file.
void write_project(const ScratchDir& dir, const std::string& radius) {
  std::ofstream out(dir / "spine.xml");
  out << "<pipe radius=\"" << radius << "\" degree=\"2\">\n  <point at=\"0,0,0\"/>\n"
      << "  <point at=\"0,10,0\" weight=\"0.70710678118654757\"/>\n  <point at=\"-10,10,0\"/>\n"
      << "</pipe>\n";
}

TEST(PipeCli, APipeProjectGivesTheSpineAndTheRadius) {
  const ScratchDir dir("pipe_cli_xml");
  write_project(dir, "2");
  const CliRun run =
      run_cli({"pipe", (dir / "spine.xml").string(), "--out", (dir / "out").string()}, dir);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("κ_max 0.1 1/mm"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("pipe r = 2 mm: exact surface"), std::string::npos) << run.out;
  const CliRun over = run_cli(
      {"pipe", (dir / "spine.xml").string(), "--radius", "11", "--out", (dir / "out2").string()},
      dir);
  EXPECT_EQ(over.status, 2) << over.err;
  EXPECT_NE(over.err.find("--radius 11 mm: the pipe self-intersects"), std::string::npos)
      << over.err;
  EXPECT_FALSE(fs::exists(dir / "out2"));
}

TEST(PipeCli, ABadPipeProjectNamesTheLine) {
  const ScratchDir dir("pipe_cli_xml_bad");
  write_project(dir, "-2");
  const CliRun run =
      run_cli({"pipe", (dir / "spine.xml").string(), "--out", (dir / "out").string()}, dir);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("spine.xml:1: <pipe> attribute 'radius': expected a number > 0"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
  write_project(dir, "");
  const CliRun none =
      run_cli({"pipe", (dir / "spine.xml").string(), "--out", (dir / "out").string()}, dir);
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.err.find("--radius: required"), std::string::npos) << none.err;
}

}  // namespace
}  // namespace polarform
