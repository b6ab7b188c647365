// The fit job's files: everything listed is written, report.json carries the documented fields
// with sane values (poles, warnings, rejected outliers), deviation.ply holds one point per input
// point, and a broken scan stops the job with an error naming its line before anything is written.
#include "jobs/fit/fit_outputs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "src/error.h"
#include "src/io/point_cloud.h"
#include "tests/support/designers/synthetic_scans.h"
#include "tests/support/jobs/job_test_support.h"

namespace polarform {
namespace {

using test::example;
using test::files_in;
using test::read_json;
using test::scratch_dir;
using test::write_text;

TEST(FitOutputs, SphereLikeExampleWritesEveryFileAndASaneReport) {
  const auto dir = scratch_dir() / "out";
  const FitJobResult r = run_fit_job(example("scans/sphere_like.xyz"));
  const std::vector<std::string> files = write_fit_outputs(r, dir);
  const std::set<std::string> expected = {"deviation.ply", "preview.svg", "report.html",
                                          "report.json",   "surface.igs", "surface.stp",
                                          "surface.x3d"};
  EXPECT_EQ(std::set<std::string>(files.begin(), files.end()), expected);
  EXPECT_EQ(files_in(dir), expected);

  const nlohmann::json j = read_json(dir / "report.json");
  EXPECT_EQ(j["command"], "fit");
  EXPECT_EQ(j["method"], "spherical");
  EXPECT_FALSE(j["reason"].get<std::string>().empty());
  EXPECT_EQ(j["input"]["points"], 3000);
  EXPECT_EQ(j["quadric"]["type"], "real ellipsoid");
  EXPECT_EQ(j["quadric"]["coefficients"].size(), 10u);
  // The example was moved by (10, -5, 20): the frame origin lands there within 0.2 mm.
  const auto& o = j["frame"]["origin"];
  EXPECT_NEAR(o[0].get<double>(), 10.0, 0.2);
  EXPECT_NEAR(o[1].get<double>(), -5.0, 0.2);
  EXPECT_NEAR(o[2].get<double>(), 20.0, 0.2);
  EXPECT_EQ(j["degrees"]["F"], nlohmann::json::array({3, 3}));
  EXPECT_EQ(j["degrees"]["nurbs"], nlohmann::json::array({5, 5}));
  // The net is the data's choice (GCV over net sizes), within one coefficient per 4 points.
  const auto& net = j["control_net_choice"];
  EXPECT_EQ(net["chosen_by"], "gcv over net sizes");
  EXPECT_EQ(net["max_coefficients"], 750);
  EXPECT_EQ(j["control_net"]["F"], net["net"]);
  EXPECT_LE(j["control_net"]["F"][0].get<int>() * j["control_net"]["F"][1].get<int>(), 750);
  EXPECT_GE(net["candidates"].size(), 3u);
  EXPECT_FALSE(j["revolution"]["rotational"].get<bool>());
  EXPECT_LT(j["revolution"]["f_test"]["p_value"].get<double>(), 1e-3);
  // The quadric frame and the least-squares centre were both fitted; the kept one is the chosen
  // candidate, within 0.1 % of the smallest rms (later frames win such ties).
  ASSERT_GE(j["frame_candidates"].size(), 2u);
  double best = 1e300, chosen = -1.0;
  int chosen_count = 0;
  for (const auto& c : j["frame_candidates"]) {
    if (!c["rms_mm"].is_null()) best = std::min(best, c["rms_mm"].get<double>());
    if (c["chosen"].get<bool>()) chosen = c["rms_mm"].get<double>(), ++chosen_count;
  }
  EXPECT_EQ(chosen_count, 1);
  EXPECT_DOUBLE_EQ(chosen, j["error_mm"]["rms"].get<double>());
  EXPECT_LE(chosen, best * (1.0 + 1e-3));
  const auto& e = j["error_mm"];
  EXPECT_EQ(e["count"], 3000);
  // Noise 0.02 mm per coordinate: the error is of that order and its statistics are ordered.
  EXPECT_GT(e["rms"].get<double>(), 0.015);
  EXPECT_LT(e["rms"].get<double>(), 0.06);
  EXPECT_LE(e["p95"].get<double>(), e["p99"].get<double>());
  EXPECT_LE(e["p99"].get<double>(), e["max"].get<double>());
  EXPECT_LT(j["seam"]["gap_mm"].get<double>(), 1e-12);
  EXPECT_GT(j["timings_s"]["total"].get<double>(), 0.0);
  EXPECT_GE(j["timings_s"]["total"].get<double>(), j["timings_s"]["read"].get<double>());

  const PointCloud deviation = read_point_cloud(dir / "deviation.ply");
  EXPECT_EQ(deviation.points.cols(), 3000);
  EXPECT_TRUE(deviation.points.isApprox(r.points, 0.0));

  // Its default G0 poles: data within 4° of each, and normals that spread by more than 1° there
  // (σ = 0.02 mm over 3000 points leaves F_u near the pole to the noise): creased, and said so.
  for (const char* pole : {"north", "south"}) {
    const auto& p = j["poles"][pole];
    EXPECT_EQ(p["treatment"], "g0");
    EXPECT_LT(p["nearest_data_deg"].get<double>(), 4.0);
    EXPECT_EQ(p["extrapolated"], false);
    EXPECT_GT(p["measured"]["normal_spread_deg"].get<double>(), 1.0);
    EXPECT_EQ(p["measured"]["creased"], true);
  }
  ASSERT_EQ(j["warnings"].size(), 2u);
  EXPECT_EQ(j["warnings"][0].get<std::string>().rfind(
                "spherical fit: the north pole creases: its normals spread by ", 0),
            0u);
  EXPECT_EQ(j["warnings"], nlohmann::json(r.warnings));
  EXPECT_FALSE(j.contains("outliers"));  // only with reject_outliers
}

TEST(FitOutputs, RejectedOutliersAreReported) {
  Eigen::Matrix3Xd p = vase_cloud(6000, 0.02, 21);
  for (Eigen::Index k = 0; k < 6000; k += 1500)  // four points 3 mm off the vase, radially
    p.col(k).head<2>() *= 1 + 3.0 / p.col(k).head<2>().norm();
  FitJobOptions o;
  o.reject_outliers = true;
  o.ctrl = std::pair{16, 16};
  const FitJobResult r = run_fit_job(p, "vase.xyz", o);
  const nlohmann::ordered_json j = fit_report_fields(r);
  ASSERT_TRUE(j.contains("outliers"));
  const auto& out = j["outliers"];
  EXPECT_EQ(out["rejected"], 4);
  EXPECT_EQ(out["threshold_sigma"], 8.0);
  EXPECT_NEAR(out["sigma_mm"].get<double>(), 0.02, 0.004);
  EXPECT_NEAR(out["threshold_mm"].get<double>(), 8 * out["sigma_mm"].get<double>(), 1e-12);
  EXPECT_GT(out["largest_mm"].get<double>(), 1.0);
  EXPECT_EQ(j["error_mm"]["count"], 5996);
  EXPECT_NEAR(j["error_mm"]["rms"].get<double>(), 0.02, 0.002);
  EXPECT_EQ(j["input"]["points"], 6000);
  EXPECT_EQ(outlier_summary(r).rfind("Outliers: 4 of 6000 points rejected at > 8 σ (σ = ", 0), 0u)
      << outlier_summary(r);
  const std::string html = render_fit_outputs(r).at("report.html");
  EXPECT_NE(html.find("Outliers: 4 of 6000 points rejected"), std::string::npos);
}

// Issue 19: every frame candidate with its numbers (the PCA + profile refinement one included,
// exactly one marked chosen), and every point's foot-point search accounted for: converged from
// the synchronized start, after the restart, or not at all (with the reason), none dropped.
TEST(FitOutputs, FrameCandidatesAndFootPointsAreReported) {
  const FitJobResult r = run_fit_job(vase_cloud(6000, 0.001, 23), "vase.xyz");
  const nlohmann::ordered_json j = fit_report_fields(r);
  EXPECT_EQ(j["method"], "cylindrical");
  const auto& list = j["frame_candidates"];
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[2]["name"], "PCA + profile refinement");
  int chosen = 0;
  for (const auto& c : list) {
    ASSERT_FALSE(c["rms_mm"].is_null()) << c.dump();
    EXPECT_TRUE(c["F"] == "F(u) alone" || c["F"] == "F(u, v)") << c.dump();
    EXPECT_GT(c["coefficients"].get<long>(), 0);
    EXPECT_EQ(c["points"], 6000);
    chosen += c["chosen"].get<bool>() ? 1 : 0;
  }
  EXPECT_EQ(chosen, 1);
  // The synthetic vase has a real cos 2θ term: F(u, v) in every frame.
  EXPECT_FALSE(j["revolution"]["rotational"].get<bool>()) << j["reason"];
  const auto& fp = j["foot_points"];
  EXPECT_EQ(fp["searched"], 6000);
  EXPECT_EQ(fp["dropped"], 0);
  EXPECT_EQ(fp["converged_first"].get<long>() + fp["restarted"].get<long>() +
                fp["unconverged"].get<long>(),
            6000);
  EXPECT_EQ(fp["unconverged"], j["error_mm"]["unconverged_foot_points"]);
  EXPECT_EQ(fp["unconverged"].get<long>() == 0, fp["unconverged_reason"].is_null());
  EXPECT_FALSE(fp["restart"].get<std::string>().empty());
}

TEST(FitOutputs, PolarProfileWritesCurveFilesWithDxf) {
  const auto dir = scratch_dir();
  std::string text = "x,y,z\n";
  for (int k = 0; k < 360; ++k) {
    const double t = k * 3.14159265358979 / 180;
    text += std::to_string(30 * std::cos(t) * (1 + 0.05 * std::cos(3 * t))) + "," +
            std::to_string(30 * std::sin(t) * (1 + 0.05 * std::cos(3 * t))) + ",0\n";
  }
  FitJobOptions o;
  o.tolerance = 1e-4;
  const FitJobResult r = run_fit_job(write_text(dir / "profile.csv", text), o);
  EXPECT_EQ(r.method, "polar");
  const std::vector<std::string> files = write_fit_outputs(r, dir / "out");
  EXPECT_EQ(files_in(dir / "out"),
            (std::set<std::string>{"curvature.csv", "curvature.svg", "curve.dxf", "curve.igs",
                                   "curve.stp", "curve.x3d", "deviation.ply", "preview.svg",
                                   "report.html", "report.json"}));
  const nlohmann::json j = read_json(dir / "out/report.json");
  EXPECT_EQ(j["method"], "polar");
  std::ifstream in(dir / "out/curvature.csv");
  const std::string csv((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(csv.rfind("u,x [mm],y [mm],polar angle [deg],kappa [1/mm],dkappa/du [1/mm]\n", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2001);
  // r = 30 (1 + 0.05 cos 3θ) is convex (r² + 2r′² − r r″ > 0): no inflection.
  EXPECT_TRUE(j["interrogation"]["inflections_deg"].empty());
  EXPECT_EQ(j["interrogation"]["derivative_order"], 5);
  EXPECT_TRUE(j["closed"].get<bool>());
  EXPECT_EQ(j["degrees"]["nurbs"][0], 5);               // cubic F times the RQB base circle
  EXPECT_LE(j["error_mm"]["max"].get<double>(), 1e-4);  // the tolerance, measured
  EXPECT_GT(j["refinements"].get<int>(), 0);
}

// r = 30 (1 + 0.15 cos 3θ) turns inwards on each lobe's flank: six inflections where
// r² + 2r′² − r r″ = 0 (found here by bisection on the closed form); the fit reports them within
// 0.5°.
TEST(FitOutputs, ProfileInflectionsAreReportedWhereTheShapeHasThem) {
  const auto dir = scratch_dir();
  const auto r = [](double t) { return 30 * (1 + 0.15 * std::cos(3 * t)); };
  std::string text = "x,y,z\n";
  for (int k = 0; k < 1440; ++k) {
    const double t = k * std::numbers::pi / 720;
    text += std::to_string(r(t) * std::cos(t)) + "," + std::to_string(r(t) * std::sin(t)) + ",0\n";
  }
  const auto numerator = [](double t) {
    const double e = 0.15, c = std::cos(3 * t), s = std::sin(3 * t);
    return (1 + e * c) * (1 + e * c) + 18 * e * e * s * s + 9 * e * c * (1 + e * c);
  };
  std::vector<double> expected;
  for (int k = 0; k < 3600; ++k) {
    double a = k * std::numbers::pi / 1800, b = (k + 1) * std::numbers::pi / 1800;
    if (numerator(a) * numerator(b) >= 0) continue;
    for (int it = 0; it < 60; ++it) {
      const double m = 0.5 * (a + b);
      ((numerator(m) > 0) == (numerator(a) > 0) ? a : b) = m;
    }
    expected.push_back(0.5 * (a + b) * 180 / std::numbers::pi);
  }
  ASSERT_EQ(expected.size(), 6u);
  FitJobOptions o;
  o.tolerance = 1e-4;
  const FitJobResult fit = run_fit_job(write_text(dir / "lobes.csv", text), o);
  const nlohmann::json j = fit_report_json(fit, {});
  std::vector<double> found = j["interrogation"]["inflections_deg"].get<std::vector<double>>();
  std::sort(found.begin(), found.end());
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t i = 0; i < found.size(); ++i) EXPECT_NEAR(found[i], expected[i], 0.5) << i;
}

TEST(FitOutputs, NanLineIsNamedAndNothingIsWritten) {
  const auto dir = scratch_dir();
  const Eigen::Matrix3Xd sphere = sphere_cloud(300, 20.0, Eigen::Vector3d(1, 2, 3), 5);
  std::string text = "# a sphere with one bad record\n";
  for (Eigen::Index k = 0; k < sphere.cols(); ++k) {
    if (k == 4) text += "4 nan 6\n";  // line 6
    text += std::to_string(sphere(0, k)) + " " + std::to_string(sphere(1, k)) + " " +
            std::to_string(sphere(2, k)) + "\n";
  }
  const auto scan = write_text(dir / "broken.xyz", text);
  const auto out = dir / "out";
  std::filesystem::create_directories(out);
  write_text(out / "keep.txt", "old");
  try {
    write_fit_outputs(run_fit_job(scan), out);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("broken.xyz"), std::string::npos) << m;
    EXPECT_NE(m.find("line 6"), std::string::npos) << m;
    EXPECT_NE(m.find("NaN"), std::string::npos) << m;
  }
  EXPECT_EQ(files_in(out), std::set<std::string>{"keep.txt"});
  // With skip_bad the record is dropped, counted and the rest fitted.
  FitJobOptions skip;
  skip.skip_bad = true;
  const FitJobResult r = run_fit_job(scan, skip);
  EXPECT_EQ(r.dropped, 1u);
  EXPECT_EQ(r.points.cols(), 300);
  EXPECT_EQ(r.method, "spherical");
  EXPECT_LT(r.report().error.max, 1e-5);  // 6-decimal coordinates
  EXPECT_EQ(fit_report_json(r, {})["input"]["dropped"], 1);
}

TEST(FitOutputs, TooFewPointsIsAnInputError) {
  const auto dir = scratch_dir();
  EXPECT_THROW(run_fit_job(write_text(dir / "two.xyz", "0 0 0\n1 1 1\n")), InputError);
}

}  // namespace
}  // namespace polarform
