// The sweep job end to end: a ring mesh of a walled tube and a sampled elliptic prism written as
// xyz, their kinds decided, recovered and written as bundles whose report.json carries the axis or
// the extrusion, the profile and the errors; a bent tube recovered by sections (its report's
// sections block); bad options and sections that are not closed are refused by name.
#include "jobs/sweep/sweep_job.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>

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
  EXPECT_NEAR(std::abs(r.revolution->axis.direction.y()), 1.0, 1e-12);
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

// An elliptic prism (semi-axes 20 and 10, length 60) on a tilted direction, its side sampled at
// 8000 random points (no noise), written as xyz: auto decides "extrusion" by the flat normals.
std::filesystem::path write_prism(const std::filesystem::path& dir, Eigen::Vector3d& direction) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "prism.xyz";
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(2, -1, 0.5).normalized()).toRotationMatrix();
  direction = R.col(2);
  std::ofstream out(file);
  out.precision(17);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(0, 1);
  for (int k = 0; k < 8000; ++k) {
    const double t = 2 * std::numbers::pi * U(rng);
    const Eigen::Vector3d p = R * Eigen::Vector3d(20 * std::cos(t), 10 * std::sin(t), 60 * U(rng)) +
                              Eigen::Vector3d(4, 5, -6);
    out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  return file;
}

TEST(SweepJob, AutoFindsAnExtrusionAndWritesItsSolid) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "polarform_sweep_job_prism";
  std::filesystem::remove_all(dir);
  Eigen::Vector3d truth;
  const std::filesystem::path file = write_prism(dir, truth);
  SweepJobOptions o;
  o.tolerance = 2e-3;
  const SweepJobResult r = run_sweep_job(file, o);
  ASSERT_TRUE(r.evidence.has_value());
  EXPECT_TRUE(r.evidence->extrusion_like());
  EXPECT_FALSE(r.evidence->revolution_like());
  ASSERT_TRUE(r.is_extrusion);
  EXPECT_FALSE(r.revolution.has_value());  // not tried: the evidence was clear
  EXPECT_TRUE(r.tolerance_met());
  const double tilt = std::acos(std::min(1.0, std::abs(r.extrusion->direction.dot(truth))));
  EXPECT_LE(tilt, 2e-6);
  EXPECT_NEAR(r.extrusion->length(), 60, 0.05);
  const std::vector<std::string> files = write_sweep_outputs(r, dir / "out");
  for (const char* f :
       {"surface.igs", "surface.stp", "surface.x3d", "profile.igs", "profile.stp", "profile.dxf",
        "profile.svg", "solid.stp", "deviation.ply", "preview.svg", "report.json", "report.html"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  std::ifstream in(dir / "out" / "report.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["kind"], "extrusion");
  EXPECT_TRUE(j["evidence"]["extrusion_like"].get<bool>());
  EXPECT_NEAR(j["extrusion"]["length"].get<double>(), 60, 0.05);
  EXPECT_NEAR(std::abs(j["extrusion"]["direction"][2].get<double>()), std::abs(truth.z()), 1e-5);
  EXPECT_EQ(j["surface"]["degrees"][0][1], 1);
  EXPECT_EQ(j["error_mm"]["count"], 8000);
  EXPECT_LE(j["error_mm"]["max"].get<double>(), 2e-3);
  EXPECT_FALSE(j.contains("axis"));
}

// A bent tube: a torus segment (spine radius 40, tube radius 4, 90°), 6000 points, no noise.
std::filesystem::path write_bent_tube(const std::filesystem::path& dir,
                                      double sweep = 0.5 * std::numbers::pi,
                                      double tube_turn = 2 * std::numbers::pi) {
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / "bent.xyz";
  std::ofstream out(file);
  out.precision(17);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> U(0, 1);
  for (int k = 0; k < 6000; ++k) {
    const double phi = sweep * U(rng), th = tube_turn * U(rng);
    const double rho = 40 + 4 * std::cos(th);
    out << rho * std::cos(phi) << ' ' << rho * std::sin(phi) << ' ' << 4 * std::sin(th) << '\n';
  }
  return file;
}

TEST(SweepJob, SectionsBundleAndReport) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "polarform_sweep_job_sections";
  std::filesystem::remove_all(dir);
  SweepJobOptions o;
  o.kind = SweepKind::sections;
  const SweepJobResult r = run_sweep_job(write_bent_tube(dir), o);
  ASSERT_TRUE(r.is_sections);
  EXPECT_EQ(r.kind(), "sections");
  const std::vector<std::string> files = write_sweep_outputs(r, dir / "out");
  for (const char* f : {"surface.igs", "surface.stp", "surface.x3d", "sections.igs", "sections.svg",
                        "deviation.ply", "preview.svg", "report.json", "report.html"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "profile.igs"));
  std::ifstream in(dir / "out" / "report.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["kind"], "sections");
  const nlohmann::json& s = j["sections"];
  EXPECT_EQ(s["count"].get<std::size_t>(), r.sections->stations.size());
  EXPECT_EQ(s["stations"].size(), s["count"].get<std::size_t>());
  EXPECT_GE(s["count"].get<int>(), 3);
  EXPECT_EQ(s["spine"]["kind"], "curved");
  // The spine runs between the end sections' centres: a quarter of the circle of radius 40.
  EXPECT_NEAR(s["spine"]["length_mm"].get<double>(), 20 * std::numbers::pi, 0.05);
  for (const nlohmann::json& st : s["stations"]) {
    EXPECT_NEAR(st["mean_radius_mm"].get<double>(), 4.0, 2e-3);
    EXPECT_LE(st["max_mm"].get<double>(), 2e-3);
  }
  EXPECT_FALSE(j.contains("profile"));
  EXPECT_EQ(j["error_mm"]["count"], 6000);
  EXPECT_LE(j["error_mm"]["max"].get<double>(), j["tolerance_mm"].get<double>() + 2e-3);
  EXPECT_TRUE(j["timings_s"].contains("skin"));
}

TEST(SweepJob, SectionsThatAreNotClosedAreAnInputError) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "polarform_sweep_job_open_sections";
  std::filesystem::remove_all(dir);
  SweepJobOptions o;
  o.kind = SweepKind::sections;
  // Only the outer half of the tube: every section is an open arc.
  const std::filesystem::path file = write_bent_tube(dir, 0.5 * std::numbers::pi, std::numbers::pi);
  try {
    run_sweep_job(file, o);
    ADD_FAILURE() << "open sections were skinned";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("bent.xyz"), std::string::npos) << what;
    EXPECT_NE(what.find("not closed"), std::string::npos) << what;
  }
}

TEST(SweepJob, BadOptionsAreRefusedByName) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "polarform_sweep_job_bad";
  const std::filesystem::path file = write_tube(dir);
  SweepJobOptions o;
  o.kind = SweepKind::revolution;
  o.center = Eigen::Vector3d::Zero();
  EXPECT_THROW(run_sweep_job(file, o), InputError);  // --center without --axis
  o.axis = Eigen::Vector3d::UnitY();
  o.kind = SweepKind::extrusion;
  EXPECT_THROW(run_sweep_job(file, o), InputError);  // an extrusion has no axis point
  o.center.reset();
  o.axis = Eigen::Vector3d::Zero();
  EXPECT_THROW(run_sweep_job(file, o), InputError);
  EXPECT_THROW(run_sweep_job(dir / "missing.xyz", {}), InputError);
  o = {};
  o.sections = 4;  // only with the kind sections
  EXPECT_THROW(run_sweep_job(file, o), InputError);
  o.kind = SweepKind::sections;
  o.axis = Eigen::Vector3d::UnitY();  // the sections' spine starts from PCA
  EXPECT_THROW(run_sweep_job(file, o), InputError);
}

}  // namespace
}  // namespace polarform
