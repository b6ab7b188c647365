// The scan-cam job on the bundled example scan of examples/cams/roller.xml (made by
// scripts/make-example-scans.py: turned 30°, centre (12.5, -7.25), σ = 5 µm along the normal):
// the phase, the centre and the motion are recovered, the report carries them, and bad option
// combinations are refused before anything is read or written.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <string>

#include "jobs/scan_cam/scan_cam_outputs.h"
#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"
#include "tests/support/jobs/job_test_support.h"

namespace polarform {
namespace {

using test::example;
using test::files_in;
using test::read_json;
using test::scratch_dir;

TEST(ScanCamJob, FarinFairsTheRecoveredDisplacementWithinItsTolerance) {
  ScanCamJobOptions o;
  o.nominal = example("cams/roller.xml");
  o.fairing = ProfileFairingOptions{FairingMethod::farin, 0.0, 100};
  const ScanCamJobResult r = run_scan_cam_job(example("scans/cam_profile.xyz"), o);
  ASSERT_TRUE(r.fairing);
  const DisplacementFairing& f = r.fairing->fairing;
  EXPECT_DOUBLE_EQ(f.tolerance, 3 * r.scan.displacement.noise);
  ASSERT_FALSE(f.steps.empty());
  for (const FairingStep& k : f.steps) EXPECT_LE(k.jump_after, 1e-9 * f.max_jump_before);
  // s is refitted along the recovered design (flat dwells, the laws' continuity at the four
  // boundaries, smoothed to the discrepancy n·σ̂²) before Farin fairs the motions' knots.
  ASSERT_TRUE(f.refit) << f.refit_skipped;
  EXPECT_TRUE(f.refit->discrepancy_met);
  EXPECT_EQ(f.refit->breaks, 4u);
  EXPECT_EQ(f.refit->dwells, 2u);
  EXPECT_GT(f.measured_deviation, 0.0);
  EXPECT_LE(f.measured_deviation, f.tolerance);
  // The profile stays within the scan noise: s moves by less than σ̂ and stays within σ̂ of the
  // nominal's.
  EXPECT_LE(f.measured_deviation, r.scan.displacement.noise);
  EXPECT_LE(r.comparison->svaj_stats[0].max, r.scan.displacement.noise);
  // The acceptance: the acceleration's rms error against the nominal falls by at least 2×
  // (measured: 0.494 → 0.0308 mm/rad², 16×, s moved 1.9 µm with σ̂ = 5.0 µm).
  ASSERT_TRUE(r.fairing->acceleration_rms_before);
  RecordProperty("a_rms_before", format_round_trip(*r.fairing->acceleration_rms_before));
  RecordProperty("a_rms_after", format_round_trip(*r.fairing->acceleration_rms_after));
  EXPECT_LE(*r.fairing->acceleration_rms_after, *r.fairing->acceleration_rms_before / 2);
  EXPECT_EQ(*r.fairing->acceleration_rms_after, r.comparison->svaj_stats[2].rms);
  const auto dir = scratch_dir();
  write_scan_cam_outputs(r, dir);
  EXPECT_TRUE(files_in(dir).count("fairing.svg"));
  const nlohmann::json j = read_json(dir / "report.json");
  EXPECT_EQ(j["fairing"]["method"], "farin");
  EXPECT_EQ(j["fairing"]["passes"].get<std::size_t>(), f.steps.size());
  // report.json rounds to 12 significant digits.
  EXPECT_NEAR(j["fairing"]["measured_deviation_mm"].get<double>(), f.measured_deviation,
              1e-11 * f.measured_deviation);
  EXPECT_EQ(j["fairing"]["refit"]["applied"], true);
  EXPECT_EQ(j["fairing"]["refit"]["boundaries"], 4);
  EXPECT_NEAR(j["fairing"]["refit"]["deviation_mm"].get<double>(), f.refit_deviation,
              1e-11 * f.refit_deviation);
  EXPECT_NEAR(j["fairing"]["acceleration_rms_error_after"].get<double>(),
              *r.fairing->acceleration_rms_after, 1e-11 * *r.fairing->acceleration_rms_after);
  // Kjellander interpolates cubics; the recovered s is quintic.
  o.fairing->method = FairingMethod::kjellander;
  try {
    run_scan_cam_job(example("scans/cam_profile.xyz"), o);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the recovered displacement s(θ) has degree 5"),
              std::string::npos)
        << e.what();
  }
}

TEST(ScanCamJob, BundledRollerScanAgainstItsNominal) {
  ScanCamJobOptions o;
  o.nominal = example("cams/roller.xml");
  o.tolerance = 0.01;
  const ScanCamJobResult r = run_scan_cam_job(example("scans/cam_profile.xyz"), o);
  ASSERT_TRUE(r.comparison);
  EXPECT_EQ(r.follower_source, "nominal design");
  EXPECT_TRUE(r.within_tolerance);
  const auto dir = scratch_dir();
  write_scan_cam_outputs(r, dir);
  EXPECT_EQ(files_in(dir),
            (std::set<std::string>{"curvature.csv", "curvature.svg", "deviation.csv",
                                   "deviation.svg", "profile.dxf", "profile.igs", "profile.stp",
                                   "profile.svg", "profile.x3d", "report.html", "report.json",
                                   "svaj.csv", "svaj.svg", "svaj_difference.svg"}));
  const nlohmann::json j = read_json(dir / "report.json");
  EXPECT_EQ(j["command"], "scan-cam");
  // roller.xml's contour is convex everywhere (no concave radius of curvature): so is the scan's.
  EXPECT_TRUE(j["interrogation"]["inflections_deg"].empty());
  EXPECT_EQ(j["interrogation"]["derivative_order"], 5);
  EXPECT_EQ(j["scan"]["kind"], "2d");
  EXPECT_EQ(j["scan"]["contour_points"], 3600);
  EXPECT_NEAR(j["bore"]["diameter_mm"].get<double>(), 16.0, 0.002);
  EXPECT_NEAR(j["cam_frame"]["origin"][0].get<double>(), 12.5, 0.002);
  EXPECT_NEAR(j["cam_frame"]["origin"][1].get<double>(), -7.25, 0.002);
  EXPECT_NEAR(j["alignment"]["phase_deg"].get<double>(), 30.0, 0.01);
  EXPECT_FALSE(j["alignment"]["mirrored"].get<bool>());
  EXPECT_NEAR(j["displacement"]["noise_mm"].get<double>(), 0.005, 0.0005);
  EXPECT_NEAR(j["displacement"]["base_radius_mm"].get<double>(), 40.0, 0.005);
  EXPECT_NEAR(j["motion"]["lift_mm"].get<double>(), 20.0, 0.005);
  EXPECT_LT(j["nominal"]["profile_normal_deviation_mm"]["rms"].get<double>(), 0.002);
  EXPECT_LT(j["nominal"]["svaj_difference"]["s_mm"]["max"].get<double>(), 0.005);
  EXPECT_EQ(j["tolerance"]["within"], true);
  EXPECT_EQ(j["profile"]["degree"], 5);
}

TEST(ScanCamJob, BundledThreeDimensionalPlateScanFindsItsFrame) {
  // cam_plate.xyz: the design turned 35° about (1, -2, 0.5) and moved by (120, 40, -15), σ 10 µm.
  ScanCamJobOptions o;
  o.nominal = example("cams/roller.xml");
  const ScanCamJobResult r = run_scan_cam_job(example("scans/cam_plate.xyz"), o);
  const ScannedCam& s = r.scan;
  EXPECT_TRUE(s.profile.three_d);
  EXPECT_NEAR(std::abs(s.profile.thickness), 10.0, 0.005);
  const Eigen::Matrix3d truth =
      Eigen::AngleAxisd(35.0 * kRadiansPerDegree, Eigen::Vector3d(1, -2, 0.5).normalized())
          .toRotationMatrix();
  EXPECT_LT((s.cam_frame.origin - Eigen::Vector3d(120, 40, -15)).norm(), 0.005);
  EXPECT_GT(s.cam_frame.axes.col(2).dot(truth.col(2)), std::cos(1e-4));  // axis within 0.1 mrad
  EXPECT_GT(s.cam_frame.axes.col(0).dot(truth.col(0)), std::cos(1e-3));  // phase within 1 mrad
  EXPECT_LT(r.comparison->normal_stats.rms, 0.005);
  EXPECT_LT(r.comparison->svaj_stats[0].max, 0.012);
}

TEST(ScanCamJob, WithoutNominalTheFollowerComesFromTheOptions) {
  ScanCamJobOptions o;
  o.follower = Follower{FollowerKind::Roller, 0.0, 10.0};
  const ScanCamJobResult r = run_scan_cam_job(example("scans/cam_profile.xyz"), o);
  EXPECT_FALSE(r.comparison);
  EXPECT_NEAR(r.scan.base_radius, 40.0, 0.005);
  double lo = 1e9, hi = -1e9;
  for (int i = 0; i < 720; ++i) {
    double s;
    r.scan.displacement_derivatives(i * 3.14159265358979 / 360, 0, &s);
    lo = std::min(lo, s), hi = std::max(hi, s);
  }
  EXPECT_NEAR(lo, 0.0, 1e-5);  // measured from its own lowest level
  EXPECT_NEAR(hi, 20.0, 0.005);
}

// Small numbers keep their digits: the smoothing weight λ is stated to 6 significant digits, never
// rounded to "0" by fixed decimals.
TEST(ScanCamJob, ReportStatesSmallNumbersWithTheirDigits) {
  ScanCamJobOptions o;
  o.nominal = example("cams/roller.xml");
  const ScanCamJobResult r = run_scan_cam_job(example("scans/cam_profile.xyz"), o);
  const auto dir = scratch_dir();
  write_scan_cam_outputs(r, dir);
  std::ifstream in(dir / "report.html");
  std::stringstream html;
  html << in.rdbuf();
  ASSERT_LT(r.scan.displacement.lambda, 1e-3);
  EXPECT_NE(html.str().find("fairness weight λ = " + number_text(r.scan.displacement.lambda) +
                            " was chosen"),
            std::string::npos);
}

TEST(ScanCamJob, RecoveredDesignIsReportedAndWrittenAsAProjectThatReproducesTheScan) {
  // cam_profile.xyz: roller.xml turned 30° (ccw): its rise at 90°–180° is seen at 60°–150°.
  ScanCamJobOptions o;
  o.follower = Follower{FollowerKind::Roller, 0.0, 10.0};
  const ScanCamJobResult r = run_scan_cam_job(example("scans/cam_profile.xyz"), o);
  ASSERT_TRUE(r.design) << r.design_failure;
  const auto dir = scratch_dir();
  const auto project = dir / "design.xml";
  write_scan_cam_outputs(r, dir / "out", project);
  const nlohmann::json j = read_json(dir / "out" / "report.json");
  const nlohmann::json& d = j["design"];
  ASSERT_EQ(d["segments"].size(), 2u);
  EXPECT_EQ(d["phase_deg"], 0.0);
  for (const auto& seg : d["segments"]) {
    const bool rise = seg["kind"] == "rise";
    EXPECT_EQ(seg["law"], rise ? "cycloidal" : "4-5-6-7");
    EXPECT_NEAR(seg["from_deg"].get<double>(), rise ? 60.0 : 210.0, 0.02);
    EXPECT_NEAR(seg["to_deg"].get<double>(), rise ? 150.0 : 330.0, 0.02);
    EXPECT_NEAR(seg["lift_mm"].get<double>(), 20.0, 0.015);  // 3σ
    EXPECT_LT(seg["from_sd_deg"].get<double>(), 0.01);
    EXPECT_EQ(seg["candidates"].size(), 10u);
    EXPECT_TRUE(seg["indistinguishable_from"].empty());
  }
  EXPECT_LT(d["redesign_deviation"]["profile_normal_mm"]["max"].get<double>(), 0.015);
  EXPECT_NEAR(d["redesign_deviation"]["point_normal_mm"]["rms"].get<double>(), 0.005, 0.0005);
  EXPECT_EQ(j["resolution"]["resolved_up_to"], "a");
  EXPECT_FALSE(j["resolution"]["derivatives"]["j"]["resolved"].get<bool>());
  std::ifstream svg(dir / "out" / "svaj.svg");
  const std::string svaj((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  EXPECT_NE(svaj.find("unresolved"), std::string::npos);
  // The project reads back and, as the scan's nominal, matches it within the noise.
  std::vector<std::string> warnings;
  const CamProject p = read_cam_project(project, warnings);
  EXPECT_NEAR(p.cam.base_radius, 40.0, 0.015);
  ScanCamJobOptions again;
  again.nominal = project;
  const ScanCamJobResult check = run_scan_cam_job(example("scans/cam_profile.xyz"), again);
  EXPECT_LT(check.comparison->normal_stats.max, 0.015);
  EXPECT_NEAR(std::remainder(check.scan.alignment->phase, 2 * std::numbers::pi), 0.0, 1e-4);
}

TEST(ScanCamJob, WriteProjectIntoAMissingFolderWritesNothing) {
  ScanCamJobOptions o;
  const ScanCamJobResult r = run_scan_cam_job(example("scans/cam_profile.xyz"), o);
  const auto dir = scratch_dir();
  try {
    write_scan_cam_outputs(r, dir / "out", dir / "missing" / "design.xml");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--write-project"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(ScanCamJob, BadOptionCombinationsAreRefused) {
  const std::string scan = example("scans/cam_profile.xyz");
  ScanCamJobOptions tol_only;
  tol_only.tolerance = 0.01;
  EXPECT_THROW(run_scan_cam_job(scan, tol_only), InputError);
  ScanCamJobOptions both;
  both.nominal = example("cams/roller.xml");
  both.follower = Follower{FollowerKind::KnifeEdge, 0.0, 0.0};
  EXPECT_THROW(run_scan_cam_job(scan, both), InputError);
  ScanCamJobOptions cylindrical;
  cylindrical.nominal = example("cams/cylindrical.xml");
  EXPECT_THROW(run_scan_cam_job(scan, cylindrical), InputError);
  ScanCamJobOptions roller;
  roller.follower = Follower{FollowerKind::Roller, 0.0, 0.0};
  EXPECT_THROW(run_scan_cam_job(scan, roller), InputError);
}

}  // namespace
}  // namespace polarform
