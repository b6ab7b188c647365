// `polarform sweep` as a user runs it: a sweep project naming a sampled elliptic prism (exit 0,
// "extrusion" on stdout, solid.stp written), a --tol over the project's that cannot be met (exit
// 1, the achieved figure, files written), and a bad project value (exit
// 2, one line naming file, line and attribute, nothing written); --kind sections on a bent tube
// (exit 0, the section count on stdout) and on half a tube (exit 2, one line: not closed).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <random>
#include <string>

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

// A torus segment (spine radius 30, tube radius 3, 90°), only the tube's angles in [0, turn).
void write_bent_tube(const ScratchDir& dir, const std::string& name, double turn) {
  std::ofstream out(dir / name);
  out.precision(17);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> U(0, 1);
  for (int k = 0; k < 5000; ++k) {
    const double phi = 0.5 * std::numbers::pi * U(rng), th = turn * U(rng);
    const double rho = 30 + 3 * std::cos(th);
    out << rho * std::cos(phi) << ' ' << rho * std::sin(phi) << ' ' << 3 * std::sin(th) << '\n';
  }
}

TEST(SweepCli, SectionsOfABentTubeAndOfHalfATube) {
  const ScratchDir dir("sweep_cli_sections");
  write_bent_tube(dir, "bent.xyz", 2 * std::numbers::pi);
  const CliRun ok = run_cli(
      {"sweep", (dir / "bent.xyz").string(), "--kind", "sections", "--out", (dir / "out").string()},
      dir);
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(ok.out.find("sections skinned along a curved spine"), std::string::npos) << ok.out;
  EXPECT_TRUE(fs::exists(dir / "out" / "sections.igs"));
  write_bent_tube(dir, "half.xyz", std::numbers::pi);
  const CliRun half = run_cli({"sweep", (dir / "half.xyz").string(), "--kind", "sections", "--out",
                               (dir / "half").string()},
                              dir);
  EXPECT_EQ(half.status, 2);
  EXPECT_NE(half.err.find("not closed"), std::string::npos) << half.err;
  EXPECT_EQ(std::count(half.err.begin(), half.err.end(), '\n'), 1) << half.err;
  EXPECT_FALSE(fs::exists(dir / "half"));
  const CliRun one = run_cli({"sweep", (dir / "bent.xyz").string(), "--kind", "sections",
                              "--sections", "1", "--out", (dir / "one").string()},
                             dir);
  EXPECT_EQ(one.status, 2) << one.err;
}

}  // namespace
}  // namespace polarform
