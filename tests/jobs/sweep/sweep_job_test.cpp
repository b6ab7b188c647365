// The sweep job end to end: a ring mesh of a stepped turned part written as xyz, recovered and
// written as a bundle whose report.json carries the axis, the profile and the errors; bad options
// are refused by name.
#include "jobs/sweep/sweep_job.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "jobs/sweep/sweep_outputs.h"
#include "src/error.h"

namespace polarform {
namespace {

std::filesystem::path write_tube(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "tube.xyz";
  std::ofstream out(file);
  out.precision(17);
  for (double y : {0.0, 1.2})
    for (double r : {0.25, 0.4})
      for (int s = 0; s < 48; ++s) {
        const double t = 2 * std::numbers::pi * s / 48;
        out << 3 + r * std::cos(t) << ' ' << y << ' ' << r * std::sin(t) << '\n';
      }
  return file;
}

TEST(SweepJob, TubeBundleAndReport) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "polarform_sweep_job_test";
  std::filesystem::remove_all(dir);
  SweepJobOptions o;
  o.tolerance = 1e-6;
  const SweepJobResult r = run_sweep_job(write_tube(dir), o);
  EXPECT_TRUE(r.tolerance_met());
  EXPECT_NEAR(std::abs(r.revolution.axis.direction.y()), 1.0, 1e-12);
  const std::vector<std::string> files = write_sweep_outputs(r, dir / "out");
  for (const char* f :
       {"surface.igs", "surface.stp", "surface.x3d", "profile.igs", "profile.dxf", "profile.svg",
        "deviation.ply", "preview.svg", "report.json", "report.html"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  std::ifstream in(dir / "out" / "report.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["kind"], "revolution");
  EXPECT_EQ(j["profile"]["loops"].size(), 1u);
  EXPECT_TRUE(j["profile"]["loops"][0]["closed"].get<bool>());
  EXPECT_EQ(j["surface"]["degrees"][0][0], 2);
  EXPECT_LE(j["error_mm"]["max"].get<double>(), 1e-6);
  EXPECT_EQ(j["error_mm"]["count"], 192);
}

TEST(SweepJob, BadOptionsAreRefusedByName) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "polarform_sweep_job_bad";
  const std::filesystem::path file = write_tube(dir);
  SweepJobOptions o;
  o.kind = SweepKind::extrusion;
  EXPECT_THROW(run_sweep_job(file, o), InputError);
  o.kind = SweepKind::revolution;
  o.center = Eigen::Vector3d::Zero();
  EXPECT_THROW(run_sweep_job(file, o), InputError);
  EXPECT_THROW(run_sweep_job(dir / "missing.xyz", {}), InputError);
}

}  // namespace
}  // namespace polarform
