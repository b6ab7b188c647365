// The patch job end to end: a scan and its boundary file written as a user would, fitted and
// written as a bundle whose report.json carries the base, the blanket, the search, the rounds and
// the errors; the structured-grid form; bad input refused by name with nothing written.
#include "jobs/patch/patch_job.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "jobs/patch/patch_outputs.h"
#include "src/error.h"
#include "src/io/boundary_csv.h"
#include "tests/support/src/synthetic_patches.h"

namespace polarform {
namespace {

namespace fs = std::filesystem;

struct Files {
  fs::path scan, boundary;
};

Files write_patch(const fs::path& dir, char id, int n) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  const NurbsSurface s = patch_test::s8_patch(id);
  Files f{dir / "scan.xyz", dir / "boundary.csv"};
  std::ofstream scan(f.scan), boundary(f.boundary);
  scan.precision(17);
  boundary.precision(17);
  const auto sample = patch_test::sample_patch(s, n);
  for (Eigen::Index k = 0; k < n; ++k)
    scan << sample.points(0, k) << ' ' << sample.points(1, k) << ' ' << sample.points(2, k) << '\n';
  boundary << "curve,x,y,z\n";
  const auto loop = patch_test::boundary_polylines(s, 101);
  for (int c = 0; c < 4; ++c)
    for (Eigen::Index k = 0; k < 101; ++k) {
      const Eigen::Vector3d p = loop[static_cast<std::size_t>(c)].col(k);
      boundary << c << ',' << p.x() << ',' << p.y() << ',' << p.z() << '\n';
    }
  return f;
}

TEST(PatchJob, BundleAndReport) {
  const fs::path dir = fs::temp_directory_path() / "polarform_patch_job_test";
  const Files in = write_patch(dir, 'a', 3000);
  PatchJobOptions o;
  o.boundary_file = in.boundary;
  o.fit.correction_rounds = 3;
  o.fit.thin = 0.002;
  const PatchJobResult r = run_patch_job(in.scan, o);
  EXPECT_EQ(r.points.cols(), 3000);
  const std::vector<std::string> files = write_patch_outputs(r, dir / "out");
  for (const char* f : {"surface.igs", "surface.stp", "surface.x3d", "base.igs", "base.x3d",
                        "decomposition.svg", "parameters.csv", "thinned.ply", "deviation.ply",
                        "preview.svg", "report.json", "report.html"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  EXPECT_EQ(files.size(), 12u);
  std::ifstream report(dir / "out" / "report.json");
  const nlohmann::json j = nlohmann::json::parse(report);
  EXPECT_EQ(j["command"], "patch");
  EXPECT_EQ(j["base"]["kind"], "bilinear");
  EXPECT_EQ(j["boundary"]["curves"].size(), 4u);
  EXPECT_GT(j["decomposition"]["quads"].get<int>(), 0);
  EXPECT_EQ(j["search"]["polished"], true);
  EXPECT_GE(j["fit"]["rounds"].size(), 1u);
  EXPECT_EQ(j["error_mm"]["count"], 3000);
  EXPECT_NEAR(j["error_mm"]["max"].get<double>(), r.patch.error.max,
              1e-9 * r.patch.error.max);  // 12 digits in the file
  EXPECT_LT(j["thinning"]["kept"].get<int>(), 3000);
  // The S8(a) patch from polylines of its exact boundary, 3 rounds: well within 1e-3 of its size.
  EXPECT_LT(r.patch.error.max, 1e-3 * 14.0);
}

TEST(PatchJob, StructuredGridUsesTheBorderAsBoundary) {
  const fs::path dir = fs::temp_directory_path() / "polarform_patch_job_grid";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Eigen::Matrix3Xd g = patch_test::s9_grid(30, 30, 0.0);
  {
    std::ofstream scan(dir / "grid.xyz");
    scan.precision(17);
    for (Eigen::Index k = 0; k < g.cols(); ++k)
      scan << g(0, k) << ' ' << g(1, k) << ' ' << g(2, k) << '\n';
  }
  PatchJobOptions o;
  o.grid = {30, 30};
  o.fit.control_u = o.fit.control_v = 12;
  const PatchJobResult r = run_patch_job(dir / "grid.xyz", o);
  EXPECT_EQ(r.points.cols(), 28 * 28);
  EXPECT_EQ(r.patch.fit.surface.size_u(), 12);
  EXPECT_EQ(r.boundary_source, "border of the 30 × 30 grid");
}

TEST(PatchJob, BadInputIsRefusedByName) {
  const fs::path dir = fs::temp_directory_path() / "polarform_patch_job_bad";
  const Files in = write_patch(dir, 'c', 200);
  PatchJobOptions neither;
  EXPECT_THROW(run_patch_job(in.scan, neither), InputError);
  PatchJobOptions both;
  both.boundary_file = in.boundary;
  both.grid = {10, 20};
  EXPECT_THROW(run_patch_job(in.scan, both), InputError);
  PatchJobOptions grid;
  grid.grid = {10, 21};
  try {
    run_patch_job(in.scan, grid);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--grid 10,21: 210 grid points, but the scan has 200");
  }
  {
    std::ofstream bad(dir / "bad.csv");
    bad << "curve,x,y,z\n0,0,0,0\n0,1,0,x\n";
  }
  PatchJobOptions o;
  o.boundary_file = dir / "bad.csv";
  try {
    run_patch_job(in.scan, o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "bad.csv").string() + ":3: z 'x': expected a finite number");
  }
}

}  // namespace
}  // namespace polarform
