// `polarform patch` as a user runs it: a scan and its boundary file fitted into a bundle (exit 0),
// an unmet --tol (exit 1, bundle written), and bad input (exit 2, one line naming the file and
// line, nothing written).
#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/jobs/cam_job_support.h"
#include "tests/ui/cli/cli_run.h"
#include "tests/support/src/synthetic_patches.h"

namespace polarform {
namespace {

using namespace cam_job_test;

void write_inputs(const ScratchDir& dir) {
  const NurbsSurface s = patch_test::s8_patch('c');
  std::ofstream scan(dir / "scan.xyz"), boundary(dir / "boundary.csv");
  scan.precision(17);
  boundary.precision(17);
  const auto sample = patch_test::sample_patch(s, 2000);
  for (Eigen::Index k = 0; k < sample.points.cols(); ++k)
    scan << sample.points(0, k) << ' ' << sample.points(1, k) << ' ' << sample.points(2, k) << '\n';
  boundary << "curve,x,y,z\n";
  const auto loop = patch_test::boundary_polylines(s, 60);
  for (int c = 0; c < 4; ++c)
    for (Eigen::Index k = 0; k < 60; ++k) {
      const Eigen::Vector3d p = loop[static_cast<std::size_t>(c)].col(k);
      boundary << c << ',' << p.x() << ',' << p.y() << ',' << p.z() << '\n';
    }
}

TEST(PatchCli, FitsAScanIntoABundle) {
  const ScratchDir dir("patch_cli_ok");
  write_inputs(dir);
  const CliRun run =
      run_cli({"patch", (dir / "scan.xyz").string(), "--boundary", (dir / "boundary.csv").string(),
               "--out", (dir / "out").string(), "--correct", "2", "--interrogate"},
              dir);
  EXPECT_EQ(run.status, 0) << run.err;
  for (const char* f : {"curvature.x3d", "curvature.ply", "reflection.x3d"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;  // a bare --interrogate: Gaussian curvature
  EXPECT_NE(run.out.find("2000 points, boundary from the boundary file boundary.csv"),
            std::string::npos)
      << run.out;
  EXPECT_TRUE(fs::exists(dir / "out" / "surface.stp"));
  EXPECT_TRUE(fs::exists(dir / "out" / "report.html"));
}

TEST(PatchCli, AnUnmetToleranceExitsOneWithTheBundleWritten) {
  const ScratchDir dir("patch_cli_tol");
  write_inputs(dir);
  const CliRun run =
      run_cli({"patch", (dir / "scan.xyz").string(), "--boundary", (dir / "boundary.csv").string(),
               "--out", (dir / "out").string(), "--tol", "1e-15", "-q"},
              dir);
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_NE(run.err.find("--tol 1e-15 mm not met"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "report.json"));
}

TEST(PatchCli, BadInputExitsTwoAndWritesNothing) {
  const ScratchDir dir("patch_cli_bad");
  write_inputs(dir);
  {
    std::ofstream bad(dir / "bad.csv");
    bad << "curve,x,y,z\n0,0,0,0\n7,1,0,0\n";
  }
  const std::vector<std::vector<std::string>> cases = {
      {"--boundary", (dir / "bad.csv").string()},
      {"--grid", "10,20"},
      {},
      {"--boundary", (dir / "boundary.csv").string(), "--base", "quadric"},
      {"--boundary", (dir / "boundary.csv").string(), "--ctrl", "8", "--tol", "0.1"},
      {"--boundary", (dir / "boundary.csv").string(), "--thin", "150"},
  };
  const std::vector<std::string> expected = {
      "bad.csv:3: curve '7': expected 0, 1, 2 or 3",
      "--grid 10,20: 200 grid points, but the scan has 2000",
      "give the boundary: either --boundary CURVES.csv or --grid ROWS,COLS",
      "--base 'quadric'",
      "give --ctrl or --tol, not both",
      "--thin '150': expected a percentage in (0, 100)"};
  for (std::size_t k = 0; k < cases.size(); ++k) {
    std::vector<std::string> args = {"patch", (dir / "scan.xyz").string(), "--out",
                                     (dir / "out").string()};
    args.insert(args.end(), cases[k].begin(), cases[k].end());
    const CliRun run = run_cli(args, dir);
    EXPECT_EQ(run.status, 2) << k << ": " << run.err;
    EXPECT_NE(run.err.find(expected[k]), std::string::npos) << k << ": " << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
    EXPECT_FALSE(fs::exists(dir / "out")) << k;
  }
}

}  // namespace
}  // namespace polarform
