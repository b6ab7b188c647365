// The polarform binary on the fit-family commands: exit code 0 and the outputs on the bundled
// examples, exit code 2 with one error line naming the line on a broken scan, and no files then;
// a profile with its bore named as two loops, outliers refused or rejected, a pole warned about.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "tests/support/jobs/job_test_support.h"

namespace polarform {
namespace {

using test::example;
using test::files_in;
using test::read_json;
using test::scratch_dir;
using test::write_text;

struct Outcome {
  int code;
  std::string err, out;
};

std::string slurp(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs polarform with `args` (shell words), stderr (and stdout, when asked) captured into files
// of the scratch dir.
Outcome polarform(const std::string& args, const std::filesystem::path& dir,
                  bool stdout_too = false) {
  const auto err = dir / "stderr.txt", out = dir / "stdout.txt";
  const std::string cmd = std::string(POLARFORM_BINARY_DIR) + "/ui/cli/polarform " + args + " >" +
                          (stdout_too ? out.string() : "/dev/null") + " 2>" + err.string();
  const int status = std::system(cmd.c_str());
  Outcome r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(err), ""};
  if (stdout_too) {
    r.out = slurp(out);
    std::filesystem::remove(out);
  }
  return r;
}

// "x y z" lines of the points.
std::string xyz_text(const Eigen::Matrix3Xd& p) {
  std::ostringstream text;
  text.precision(10);
  for (Eigen::Index k = 0; k < p.cols(); ++k)
    text << p(0, k) << " " << p(1, k) << " " << p(2, k) << "\n";
  return text.str();
}

TEST(Cli, FitVizAndScanCamSucceedOnTheExamples) {
  const auto dir = scratch_dir();
  EXPECT_EQ(polarform("fit " + example("scans/vase.xyz") + " --out " + (dir / "vase").string() +
                          " --ctrl 14,14 --quiet",
                      dir)
                .code,
            0);
  const nlohmann::json fit = read_json(dir / "vase/report.json");
  EXPECT_EQ(fit["method"], "cylindrical");
  EXPECT_EQ(fit["control_net"]["F"], nlohmann::json::array({14, 14}));
  EXPECT_EQ(polarform("viz " + example("scans/sphere_grid.csv") + " --out " +
                          (dir / "viz").string() + " -q",
                      dir)
                .code,
            0);
  EXPECT_TRUE(std::filesystem::exists(dir / "viz/surface.x3d"));
  EXPECT_EQ(polarform("scan-cam " + example("scans/cam_profile.xyz") + " --nominal " +
                          example("cams/roller.xml") + " --tol 0.01 --out " +
                          (dir / "cam").string() + " -q",
                      dir)
                .code,
            0);
  EXPECT_NEAR(read_json(dir / "cam/report.json")["alignment"]["phase_deg"].get<double>(), 30.0,
              0.01);
}

// An inspected cam out of its tolerance still gets every output, and exit status 3 for QC scripts;
// a nominal whose base radius is far from the scan's is called out as likely the wrong one.
TEST(Cli, ScanCamOutOfToleranceExitsThreeAndSuspectsAWrongNominal) {
  const auto dir = scratch_dir();
  std::ifstream in(example("cams/roller.xml"));
  std::stringstream roller;
  roller << in.rdbuf();
  std::string wrong = roller.str();
  wrong.replace(wrong.find("base-radius=\"40\""), 16, "base-radius=\"50\"");
  write_text(dir / "wrong.xml", wrong);
  const Outcome out = polarform("scan-cam " + example("scans/cam_profile.xyz") + " --nominal " +
                                    (dir / "wrong.xml").string() + " --tol 0.05 --out " +
                                    (dir / "cam").string() + " -q",
                                dir);
  EXPECT_EQ(out.code, 3) << out.err;
  EXPECT_NE(out.err.find("polarform: out of tolerance: the profile deviates from the nominal by "
                         "up to "),
            std::string::npos)
      << out.err;
  EXPECT_NE(out.err.find("polarform: warning: the scan's base radius "), std::string::npos)
      << out.err;
  EXPECT_NE(out.err.find(" mm differs from the nominal's 50 mm by -"), std::string::npos)
      << out.err;
  EXPECT_NE(out.err.find("(wrong nominal?)"), std::string::npos) << out.err;
  EXPECT_EQ(read_json(dir / "cam/report.json")["tolerance"]["within"], false);
  // Within tolerance: exit 0 and no suspicion.
  const Outcome good = polarform("scan-cam " + example("scans/cam_profile.xyz") + " --nominal " +
                                     example("cams/roller.xml") + " --tol 0.05 --out " +
                                     (dir / "good").string() + " -q",
                                 dir);
  EXPECT_EQ(good.code, 0) << good.err;
  EXPECT_EQ(good.err.find("wrong nominal"), std::string::npos) << good.err;
}

// A fit project names the scan (relative to itself) and the options; flags override them.
TEST(Cli, FitRunsAProjectAndFlagsOverrideIt) {
  const auto dir = scratch_dir();
  ASSERT_EQ(polarform("fit " + example("scans/sphere_like_fit.xml") + " --out " +
                          (dir / "project").string() + " -q",
                      dir)
                .code,
            0);
  const nlohmann::json fit = read_json(dir / "project/report.json");
  EXPECT_EQ(fit["method"], "spherical");
  EXPECT_EQ(fit["control_net"]["F"], nlohmann::json::array({12, 24}));
  ASSERT_EQ(polarform("fit " + example("scans/sphere_like_fit.xml") + " --ctrl 10,16 --out " +
                          (dir / "override").string() + " -q",
                      dir)
                .code,
            0);
  EXPECT_EQ(read_json(dir / "override/report.json")["control_net"]["F"],
            nlohmann::json::array({10, 16}));

  write_text(dir / "bad.xml", "<polarform version=\"1\">\n<fit scan=\"a.xyz\" degree=\"3\"/>\n"
                              "</polarform>\n");
  const Outcome bad = polarform("fit " + (dir / "bad.xml").string() + " --out " +
                                    (dir / "bad").string(),
                                dir);
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("bad.xml:2: <fit> attribute 'degree'"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
}

// Fairing and base arcs from the command line or the project: for the same F, the quartic base
// raises the NURBS degrees of a spherical product from (5, 5) to (7, 7) (arcs of degree 4 instead
// of 2); GCV picks its own λ; a project's fixed λ is used as given; bad values exit 2.
TEST(Cli, FairnessAndBaseArcsReachTheFit) {
  const auto dir = scratch_dir();
  const std::string project = example("scans/sphere_like_fit.xml");
  ASSERT_EQ(polarform("fit " + project + " --out " + (dir / "rqb").string() + " -q", dir).code, 0);
  ASSERT_EQ(polarform("fit " + project + " --base quartic --out " + (dir / "quartic").string() +
                          " -q",
                      dir)
                .code,
            0);
  ASSERT_EQ(polarform("fit " + project + " --fairness gcv --out " + (dir / "gcv").string() +
                          " -q",
                      dir)
                .code,
            0);
  const nlohmann::json rqb = read_json(dir / "rqb/report.json");
  const nlohmann::json quartic = read_json(dir / "quartic/report.json");
  const nlohmann::json gcv = read_json(dir / "gcv/report.json");
  EXPECT_EQ(rqb["base"], "rqb");
  EXPECT_EQ(rqb["degrees"]["nurbs"], nlohmann::json::array({5, 5}));
  EXPECT_EQ(quartic["base"], "quartic");
  EXPECT_EQ(quartic["degrees"]["nurbs"], nlohmann::json::array({7, 7}));
  EXPECT_EQ(quartic["control_net"]["F"], rqb["control_net"]["F"]);
  EXPECT_EQ(rqb["fairness"], "relative");
  EXPECT_EQ(rqb["fairness_weight"], 1e-7);
  EXPECT_EQ(gcv["fairness"], "gcv");
  EXPECT_FALSE(gcv.contains("fairness_weight"));
  EXPECT_NE(gcv["fairness_lambda"], rqb["fairness_lambda"]);
  // Both fit the σ = 0.02 mm scan to its noise.
  for (const auto* r : {&rqb, &quartic, &gcv})
    EXPECT_LT((*r)["error_mm"]["rms"].get<double>(), 0.025);

  // A project's fixed λ, and flags that refuse bad values.
  write_text(dir / "fixed.xml",
             "<polarform version=\"1\">\n<fit scan=\"" + example("scans/sphere_like.xyz") +
                 "\" method=\"spherical\" closed=\"yes\" pole=\"g1\" fairness=\"fixed\" "
                 "lambda=\"0.001\"/>\n</polarform>\n");
  ASSERT_EQ(polarform("fit " + (dir / "fixed.xml").string() + " --out " +
                          (dir / "fixed").string() + " -q",
                      dir)
                .code,
            0);
  const nlohmann::json fixed = read_json(dir / "fixed/report.json");
  EXPECT_EQ(fixed["fairness"], "fixed");
  EXPECT_EQ(fixed["fairness_lambda"], 0.001);
  for (const char* bad : {"--fairness smooth", "--lambda 0", "--lambda -1e-3", "--base cubic"}) {
    const Outcome r =
        polarform("fit " + project + " " + bad + " --out " + (dir / "bad").string(), dir);
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find(std::string(bad).substr(0, std::string(bad).find(' '))),
              std::string::npos)
        << r.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "bad"));
}

TEST(Cli, BrokenScanExitsTwoNamingTheLineAndWritesNothing) {
  const auto dir = scratch_dir();
  const auto scan = write_text(dir / "bad.xyz", "x y z\n1 2 3\n4 5 6\n7 8 abc\n1 1 1\n");
  for (const std::string command : {"fit", "scan-cam"}) {
    const Outcome r =
        polarform(command + " " + scan.string() + " --out " + (dir / command).string(), dir);
    EXPECT_EQ(r.code, 2) << command;
    EXPECT_NE(r.err.find("bad.xyz: line 4"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / command)) << command;
  }
  const Outcome grid =
      polarform("viz " + write_text(dir / "g.csv", "p,phi_deg,theta_deg\n1,2\n").string() +
                    " --out " + (dir / "viz").string(),
                dir);
  EXPECT_EQ(grid.code, 2);
  EXPECT_NE(grid.err.find("g.csv:2:"), std::string::npos) << grid.err;
}

// The bundled cam scan with its bore is two loops: one line on stderr says so, with the radii.
TEST(Cli, FitNamesTheTwoLoopsOfAProfileWithItsBore) {
  const auto dir = scratch_dir();
  const std::string scan = example("scans/cam_profile.xyz");
  const Outcome r = polarform("fit " + scan + " --out " + (dir / "cam").string(), dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "polarform: error: " + scan +
                       ": polar curve fit: two loops found (radius about 50 mm around the centre, "
                       "radius about 8 mm around (12.5, -7.25)): use scan-cam, or remove the "
                       "inner loop\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "cam"));
}

// A profile scan (r = 30 + 2 cos 3θ, σ = 0.01 mm) with five points 4 mm off: refused with their
// count; with --reject-outliers (or the project's reject-outliers="true") fitted without them,
// the summary and report.json saying how many at what threshold.
TEST(Cli, FitRefusesAFewOutliersAndRejectsThemWhenAsked) {
  const auto dir = scratch_dir();
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> T(0, 2 * 3.141592653589793);
  std::normal_distribution<double> N(0, 0.01);
  Eigen::Matrix3Xd p(3, 3005);
  for (Eigen::Index k = 0; k < p.cols(); ++k) {
    const double t = T(rng), r = 30 + 2 * std::cos(3 * t) +
                                 (k < 3000 ? N(rng)
                                  : k % 2  ? 4.0
                                           : -4.0);
    p.col(k) << r * std::cos(t), r * std::sin(t), 0.0;
  }
  const std::string scan = write_text(dir / "spiky.xyz", xyz_text(p)).string();
  const Outcome refused = polarform("fit " + scan + " --out " + (dir / "a").string(), dir);
  EXPECT_EQ(refused.code, 2);
  EXPECT_EQ(refused.err.rfind("polarform: error: " + scan +
                                  ": polar curve fit: 5 outliers of 3005 points at > 8 σ (σ = ",
                              0),
            0u)
      << refused.err;
  EXPECT_NE(refused.err.find("): rerun with --reject-outliers\n"), std::string::npos)
      << refused.err;
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1);
  EXPECT_FALSE(std::filesystem::exists(dir / "a"));

  const Outcome fitted = polarform(
      "fit " + scan + " --reject-outliers --ctrl 24 --out " + (dir / "b").string(), dir, true);
  ASSERT_EQ(fitted.code, 0) << fitted.err;
  EXPECT_EQ(fitted.err, "");
  EXPECT_NE(fitted.out.find("\nOutliers: 5 of 3005 points rejected at > 8 σ (σ = 0.0"),
            std::string::npos)
      << fitted.out;
  EXPECT_NE(fitted.out.find("the distances are of the 3000 points kept.\ndistance to the fit over "
                            "3000 points: rms "),
            std::string::npos)
      << fitted.out;
  const nlohmann::json report = read_json(dir / "b/report.json");
  EXPECT_EQ(report["outliers"]["rejected"], 5);
  EXPECT_EQ(report["outliers"]["threshold_sigma"], 8.0);
  EXPECT_NEAR(report["outliers"]["sigma_mm"].get<double>(), 0.01, 0.0015);
  EXPECT_NEAR(report["outliers"]["largest_mm"].get<double>(), 4.0, 0.05);
  EXPECT_EQ(report["error_mm"]["count"], 3000);
  EXPECT_NEAR(report["error_mm"]["rms"].get<double>(), 0.01, 0.001);
  EXPECT_EQ(report["warnings"], nlohmann::json::array());

  write_text(dir / "fit.xml",
             "<polarform version=\"1\"><fit scan=\"spiky.xyz\" "
             "reject-outliers=\"true\"/></polarform>\n");
  ASSERT_EQ(
      polarform("fit " + (dir / "fit.xml").string() + " -q --out " + (dir / "c").string(), dir)
          .code,
      0);
  EXPECT_EQ(read_json(dir / "c/report.json")["outliers"]["rejected"], 5);

  const Outcome help = polarform("fit --help", dir, true);
  EXPECT_NE(help.out.find("--reject-outliers"), std::string::npos) << help.out;
}

// A G1 pole closed over a 25° hole rests on no data: a warning on stderr (also with -q) and in
// report.json; scanned to the poles, none.
TEST(Cli, FitWarnsAboutAnExtrapolatedPole) {
  const auto dir = scratch_dir();
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> C(-1.0, std::cos(25 * 3.141592653589793 / 180)),
      T(0, 2 * 3.141592653589793);
  Eigen::Matrix3Xd p(3, 4000);
  for (Eigen::Index k = 0; k < p.cols(); ++k) {
    const double c = C(rng), s = std::sqrt(1 - c * c), t = T(rng);
    p.col(k) << 25 * s * std::cos(t), 25 * s * std::sin(t), 25 * c;
  }
  const std::string scan = write_text(dir / "gap.xyz", xyz_text(p)).string();
  const Outcome r = polarform("fit " + scan +
                                  " --method spherical --pole g1 --center 0,0,0 "
                                  "--axis 0,0,1 -q --out " +
                                  (dir / "gap").string(),
                              dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.rfind("polarform: warning: " + scan +
                            ": spherical fit: the north pole is extrapolated: no data within 10° "
                            "of it (the nearest point is 25.",
                        0),
            0u)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  const nlohmann::json report = read_json(dir / "gap/report.json");
  EXPECT_EQ(report["poles"]["north"]["extrapolated"], true);
  EXPECT_NEAR(report["poles"]["north"]["nearest_data_deg"].get<double>(), 25.0, 0.2);
  EXPECT_EQ(report["poles"]["south"]["extrapolated"], false);
  ASSERT_EQ(report["warnings"].size(), 1u);
  EXPECT_EQ("polarform: warning: " + scan + ": " + report["warnings"][0].get<std::string>() + "\n",
            r.err);
}

// --pole takes every treatment a project can state, g0 included, over the whole cloud's poles.
TEST(Cli, FitPoleOptionTakesG0) {
  const auto dir = scratch_dir();
  const Outcome r = polarform(
      "fit " + example("scans/sphere_like.xyz") + " --pole g0 -q --out " + (dir / "g0").string(),
      dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json report = read_json(dir / "g0/report.json");
  EXPECT_EQ(report["poles"]["north"]["treatment"], "g0");
  EXPECT_EQ(report["poles"]["south"]["treatment"], "g0");
}

TEST(Cli, BadOptionsExitTwo) {
  const auto dir = scratch_dir();
  const std::string scan = example("scans/vase.xyz");
  EXPECT_EQ(polarform("fit " + scan + " --out " + (dir / "a").string() + " --degree 3,x", dir).code,
            2);
  EXPECT_EQ(
      polarform("fit " + scan + " --out " + (dir / "b").string() + " --ctrl 8 --tol 0.1", dir).code,
      2);
  EXPECT_EQ(
      polarform("fit " + scan + " --out " + (dir / "c").string() + " --method conical", dir).code,
      2);
  const Outcome r = polarform(
      "scan-cam " + example("scans/cam_profile.xyz") + " --tol 0.01 --out " + (dir / "d").string(),
      dir);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--nominal"), std::string::npos) << r.err;
  EXPECT_EQ(files_in(dir), std::set<std::string>{"stderr.txt"});
}

}  // namespace
}  // namespace polarform
