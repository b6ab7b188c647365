// `polarform sweep` as a user runs it: a sweep project naming a sampled elliptic prism (exit 0,
// "extrusion" on stdout, solid.stp written), a --tol over the project's that cannot be met (exit
// 1, the achieved figure, files written), and a bad project value (exit
// 2, one line naming file, line and attribute, nothing written).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <numbers>
#include <random>

#include "tests/support/jobs/cam_job_support.h"
#include "tests/ui/cli/cli_run.h"

namespace polarform {
namespace {

using namespace cam_job_test;

void write_prism(const ScratchDir& dir) {
  std::ofstream out(dir / "prism.xyz");
  out.precision(17);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(0, 1);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 0.5, 0).normalized()).toRotationMatrix();
  for (int k = 0; k < 6000; ++k) {
    const double t = 2 * std::numbers::pi * U(rng);
    const Eigen::Vector3d p = R * Eigen::Vector3d(15 * std::cos(t), 9 * std::sin(t), 40 * U(rng));
    out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
}

TEST(SweepCli, AProjectRunsAndFlagsOverrideIt) {
  const ScratchDir dir("sweep_cli_ok");
  write_prism(dir);
  std::ofstream(dir / "prism_sweep.xml")
      << "<polarform version=\"1\">\n  <sweep scan=\"prism.xyz\" tolerance=\"0.002\"/>\n"
         "</polarform>\n";
  const CliRun run =
      run_cli({"sweep", (dir / "prism_sweep.xml").string(), "--out", (dir / "out").string()}, dir);
  EXPECT_EQ(run.status, 0) << run.err;
  EXPECT_NE(run.out.find("extrusion along"), std::string::npos) << run.out;
  EXPECT_TRUE(fs::exists(dir / "out" / "solid.stp"));
  // --tol over the project's tolerance: far below what the section fit can reach, so it is
  // missed (exit 1 with the achieved figure), and the files are written all the same.
  const CliRun strict = run_cli({"sweep", (dir / "prism_sweep.xml").string(), "--tol", "1e-9",
                                 "--out", (dir / "strict").string()},
                                dir);
  EXPECT_EQ(strict.status, 1) << strict.err;
  EXPECT_NE(strict.err.find("--tol 1e-09 mm not met: the max distance is "), std::string::npos)
      << strict.err;
  EXPECT_TRUE(fs::exists(dir / "strict" / "report.json"));
}

TEST(SweepCli, ABadProjectValueIsOneLineAndWritesNothing) {
  const ScratchDir dir("sweep_cli_bad");
  write_prism(dir);
  std::ofstream(dir / "bad.xml") << "<polarform version=\"1\">\n  <sweep scan=\"prism.xyz\" "
                                    "kind=\"extrusion\" axis=\"0,0,1\" center=\"1,2,3\"/>\n"
                                    "</polarform>\n";
  const CliRun run =
      run_cli({"sweep", (dir / "bad.xml").string(), "--out", (dir / "out").string()}, dir);
  EXPECT_EQ(run.status, 2);
  EXPECT_NE(run.err.find("bad.xml:2: <sweep> attribute 'center'"), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace polarform
