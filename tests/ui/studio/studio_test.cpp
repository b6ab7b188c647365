// polarform-studio end to end under Xvfb + Mesa: every workspace renders a settled frame that is
// not blank (pixel statistics of the PNG), a scripted edit (--bench-frames) changes the numbers
// the app reports, scripts (--script) drive undo/redo, save as, every export, drag-and-drop and
// the state kept between runs, and bad input — a broken project, an infeasible design, a bad
// script — is reported while the app keeps running. Skips with a message when Xvfb or the
// studio binary is missing.
#include <gtest/gtest.h>

#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <set>
#include <sstream>
#include <string>

#include "designers/convert/occt_peer.h"
#include "designers/convert/sisl_peer.h"
#include "jobs/project/cam_project.h"
#include "jobs/project/fit_project.h"
#include "jobs/report/report_lines.h"
#include "tests/ui/studio/xvfb_server.h"

namespace {

namespace fs = std::filesystem;

const fs::path kStudio = fs::path(POLARFORM_BINARY_DIR) / "ui" / "studio" / "polarform-studio";
const fs::path kExamples = fs::path(POLARFORM_SOURCE_DIR) / "examples";

struct StudioRun {
  int status = -1;
  std::string output;  // stdout and stderr
};

StudioRun run_once(const std::string& command) {
  StudioRun r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) r.output += buffer;
  const int status = pclose(pipe);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// The test process's X server, started at the first use.
const polarform::studio_test::XvfbServer& x_server() {
  static const polarform::studio_test::XvfbServer server;
  return server;
}

// Runs the app on the test process's own Xvfb display.
StudioRun run_studio(const std::string& arguments) {
  return run_once(
      // A fixed SOURCE_DATE_EPOCH stamps the exported IGES and STEP files alike, so that they can
      // be compared byte for byte with the CLI's.
      "DISPLAY=" + x_server().display().value_or("") + " SOURCE_DATE_EPOCH=1700000000 '" +
      kStudio.string() + "' " + arguments + " 2>&1");
}

// "key=value" lines of one block of the output (after `header`, up to the next other line); a key
// has no spaces, so a message that happens to contain '=' is not one.
std::map<std::string, std::string> numbers(const std::string& output,
                                           const std::string& header = "") {
  std::map<std::string, std::string> out;
  std::istringstream in(output);
  std::string line;
  bool inside = header.empty();
  while (std::getline(in, line)) {
    if (!inside) {
      inside = line == header;
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos || line.find(' ') < eq) {
      if (!out.empty()) break;
      continue;
    }
    out[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return out;
}

double number(const std::map<std::string, std::string>& m, const std::string& key) {
  const auto it = m.find(key);
  if (it == m.end()) {
    ADD_FAILURE() << "no '" << key << "' in the reported numbers";
    return std::nan("");
  }
  return std::stod(it->second);
}

int error_count(const std::string& output) {
  const auto at = output.rfind("errors: ");
  return at == std::string::npos ? -1 : std::stoi(output.substr(at + 8));
}

struct PixelStats {
  int width = 0, height = 0;
  double luminance_stddev = 0.0;
  std::size_t colours = 0;      // distinct RGB values
  double off_background = 0.0;  // fraction of pixels differing from the most common colour
};

PixelStats pixel_stats(const fs::path& png) {
  PixelStats s;
  int channels = 0;
  unsigned char* data = stbi_load(png.c_str(), &s.width, &s.height, &channels, 3);
  if (!data) return s;
  const std::size_t n = static_cast<std::size_t>(s.width) * s.height;
  std::map<unsigned, std::size_t> histogram;
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char* p = data + 3 * i;
    const double y = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    sum += y;
    sum2 += y * y;
    ++histogram[(p[0] << 16) | (p[1] << 8) | p[2]];
  }
  stbi_image_free(data);
  const double mean = sum / n;
  s.luminance_stddev = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
  s.colours = histogram.size();
  std::size_t most = 0;
  for (const auto& [colour, count] : histogram) most = std::max(most, count);
  s.off_background = 1.0 - static_cast<double>(most) / n;
  return s;
}

class StudioTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!x_server().display())
      GTEST_SKIP() << "no Xvfb display: install the Debian packages xvfb and libgl1-mesa-dri "
                      "(scripts/install-deps.sh) to run the studio tests";
    if (!fs::exists(kStudio))
      GTEST_SKIP() << "polarform-studio was not built (" << kStudio
                   << "); build it with POLARFORM_BUILD_STUDIO=ON";
    dir_ = fs::temp_directory_path() /
           ("polarform_studio_test_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    if (!dir_.empty()) fs::remove_all(dir_, ec);
  }

  // Renders `workspace` for `project` and checks the picture is a real frame, not a blank one.
  StudioRun screenshot(const fs::path& project, const std::string& workspace, int width = 1280,
                       int height = 800) {
    const fs::path png = dir_ / (workspace + ".png");
    StudioRun r = run_studio("--project '" + project.string() + "' --workspace " + workspace +
                             " --screenshot '" + png.string() + "' --size " +
                             std::to_string(width) + "x" + std::to_string(height));
    EXPECT_EQ(r.status, 0) << r.output;
    const PixelStats s = pixel_stats(png);
    EXPECT_EQ(s.width, width) << r.output;
    EXPECT_EQ(s.height, height);
    EXPECT_GT(s.luminance_stddev, 20.0) << "a nearly uniform picture";
    EXPECT_GT(s.colours, 500u) << "too few colours for plots, text and shading";
    EXPECT_GT(s.off_background, 0.2) << "most of the picture is one colour";
    return r;
  }

  fs::path write(const std::string& name, const std::string& text) {
    const fs::path file = dir_ / name;
    std::ofstream(file) << text;
    return file;
  }

  fs::path dir_;
};

// The text of a file.
std::string slurp(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Control points of the first rational B-spline curve (entity 126) of an IGES file: its first
// parameter K is the upper index of the control points.
int iges_curve_control_points(const fs::path& igs) {
  const std::string text = slurp(igs);
  const auto at = text.find("\n126,");
  if (at == std::string::npos) return -1;
  return std::stoi(text.substr(at + 5)) + 1;
}

// The columns of a CSV file with one header line.
std::vector<std::vector<double>> csv_columns(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::vector<double>> columns;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::string cell;
    for (std::size_t k = 0; std::getline(row, cell, ','); ++k) {
      if (columns.size() <= k) columns.emplace_back();
      columns[k].push_back(std::stod(cell));
    }
  }
  return columns;
}

TEST_F(StudioTest, CamWorkspaceRendersAndMeetsItsTolerance) {
  const StudioRun r = screenshot(kExamples / "cams" / "roller.xml", "cam");
  const auto n = numbers(r.output);
  EXPECT_EQ(number(n, "segments"), 4);
  EXPECT_NEAR(number(n, "stroke_mm"), 20.0, 1e-9);
  EXPECT_GT(number(n, "report.max_pressure_angle_deg"), 5.0);
  EXPECT_LT(number(n, "report.max_pressure_angle_deg"), 45.0);
  EXPECT_GT(number(n, "report.arcs"), 0);
  EXPECT_LE(number(n, "report.max_radial_error_mm"), number(n, "report.tolerance_mm"));
  EXPECT_EQ(error_count(r.output), 0) << r.output;
}

// The layout adapts to a small window: panels keep their minimum sizes and the design still
// computes (the smallest size --size accepts is 320x240).
TEST_F(StudioTest, SmallWindowsStillShowTheWorkspaces) {
  const StudioRun cam = screenshot(kExamples / "cams" / "roller.xml", "cam", 640, 400);
  EXPECT_LE(number(numbers(cam.output), "report.max_radial_error_mm"),
            number(numbers(cam.output), "report.tolerance_mm"));
  const StudioRun vessel =
      screenshot(kExamples / "vessels" / "hemispherical.xml", "vessel", 800, 480);
  EXPECT_EQ(number(numbers(vessel.output), "solved"), 1) << vessel.output;
}

TEST_F(StudioTest, StudyWorkspaceRendersAToleranceSweep) {
  const StudioRun r = screenshot(kExamples / "cams" / "roller.xml", "study");
  const auto n = numbers(r.output);
  EXPECT_EQ(number(n, "studied"), 1) << r.output;
  EXPECT_EQ(number(n, "tolerances"), 9);
  EXPECT_LE(number(n, "tightest_quartic_error_mm"), number(n, "tightest_tolerance_mm"));
  // The point of the quasi-uniform quartic base: far fewer control points than the RQB base.
  EXPECT_LT(number(n, "tightest_quartic_control_points"), number(n, "tightest_rqb_control_points"));
  // The compact profiles beside the peers' fits at 1e-6 mm, the ratio their counts divided (the
  // fewest of the fits found; a peer that found none shows 0).
  const double exact = number(n, "tightest_exact_control_points");
  EXPECT_GT(exact, 0);
  EXPECT_GT(number(n, "tightest_degree3_control_points"), 0);
  const bool peers = polarform::kOcctPeersAvailable || polarform::kSislPeersAvailable;
  EXPECT_EQ(number(n, "peers"), peers ? 1 : 0);
  if (polarform::kOcctPeersAvailable) {
    double best = 0;
    for (const char* key :
         {"tightest_occt_degree3_control_points", "tightest_occt_best_control_points",
          "tightest_sisl_degree3_control_points", "tightest_sisl_best_control_points"}) {
      const double count = number(n, key);
      if (count > 0 && (best == 0 || count < best)) best = count;
    }
    ASSERT_GT(best, 0);
    EXPECT_NEAR(number(n, "tightest_exact_to_best_peer"), exact / best, 1e-8);
  }
  EXPECT_EQ(error_count(r.output), 0) << r.output;
}

TEST_F(StudioTest, VesselWorkspaceRendersASolvedHead) {
  const StudioRun r = screenshot(kExamples / "vessels" / "torispherical_100_6.xml", "vessel");
  const auto n = numbers(r.output);
  EXPECT_EQ(number(n, "solved"), 1) << r.output;
  EXPECT_GT(number(n, "report.head.depth_mm"), 50.0);
  EXPECT_LT(number(n, "report.head.depth_mm"), 500.0);
  EXPECT_EQ(error_count(r.output), 0) << r.output;
}

TEST_F(StudioTest, FitWorkspaceRendersTheFittedScan) {
  // An ellipsoid-like scan, open at the bottom, with noise.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::ostringstream text;
  for (int i = 0; i < 8000; ++i) {
    const double z = -0.8 + 1.8 * u(rng), phi = std::acos(std::min(1.0, z)),
                 theta = 2 * std::numbers::pi * u(rng);
    const double r =
        40.0 * (1.0 + 0.05 * std::cos(2 * theta) * std::sin(phi) * std::sin(phi)) + noise(rng);
    text << r * std::sin(phi) * std::cos(theta) + 10 << ' '
         << 0.8 * r * std::sin(phi) * std::sin(theta) << ' ' << 0.6 * r * std::cos(phi) + 5 << '\n';
  }
  const StudioRun r = screenshot(write("scan.xyz", text.str()), "fit");
  const auto n = numbers(r.output);
  EXPECT_EQ(number(n, "points"), 8000);
  EXPECT_EQ(number(n, "fitted"), 1) << r.output;
  EXPECT_LT(number(n, "report.error_mm.rms"), 1.0);
}

// A fit project sets the options and names the scan: a closed spherical fit, G1 poles, 12 x 24.
TEST_F(StudioTest, FitWorkspaceOpensAFitProject) {
  const StudioRun r = screenshot(kExamples / "scans" / "sphere_like_fit.xml", "fit");
  const auto n = numbers(r.output);
  EXPECT_EQ(number(n, "points"), 3000) << r.output;
  EXPECT_EQ(number(n, "fitted"), 1) << r.output;
  EXPECT_EQ(n.at("report.method"), "spherical") << r.output;
  // Bicubic F of 12 x 24 times the RQB base sphere: (5, 5), 35 x 81 control points.
  EXPECT_EQ(number(n, "report.control_net.nurbs.0"), 35) << r.output;
  EXPECT_EQ(number(n, "report.control_net.nurbs.1"), 81) << r.output;
  EXPECT_LT(number(n, "report.error_mm.rms"), 0.03);  // σ = 0.02 mm
  EXPECT_EQ(error_count(r.output), 0) << r.output;
}

// A cam's profile scan in the fit workspace: the recovered design exported from the studio is the
// project `polarform scan-cam --write-project` writes, byte for byte, the scan-cam outputs are the
// CLI's, the numbers shown are report.json's, and the design opens in the cam workspace with the
// recovered laws.
TEST_F(StudioTest, FitWorkspaceRecoversACamDesignAsTheCliDoes) {
  const fs::path scan = kExamples / "scans" / "cam_profile.xyz";
  const fs::path script = write("scan.txt", "open \"" + scan.string() +
                                                "\"\nexport design studio_design.xml\n"
                                                "export scan-cam studio_outputs\nnumbers scan\n"
                                                "open studio_design.xml\nnumbers design\n");
  const StudioRun r =
      run_studio("--script '" + script.string() + "' --size 1280x800 --state-dir '" +
                 (dir_ / "state").string() + "'");
  // The one error: the surface fit on opening, which refuses the cam's bore as a second loop.
  EXPECT_EQ(error_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("two loops found"), std::string::npos) << r.output;
  const std::string cli = (fs::path(POLARFORM_BINARY_DIR) / "ui" / "cli" / "polarform").string();
  ASSERT_EQ(std::system(("SOURCE_DATE_EPOCH=1700000000 '" + cli + "' scan-cam '" + scan.string() +
                         "' --out '" + (dir_ / "cli_outputs").string() + "' --write-project '" +
                         (dir_ / "cli_design.xml").string() + "' -q 2>/dev/null")
                            .c_str()),
            0);
  EXPECT_EQ(slurp(dir_ / "studio_design.xml"), slurp(dir_ / "cli_design.xml"));
  for (const char* file : {"svaj.csv", "deviation.csv", "profile.igs"}) {
    if (fs::exists(dir_ / "cli_outputs" / file)) {
      EXPECT_EQ(slurp(dir_ / "studio_outputs" / file), slurp(dir_ / "cli_outputs" / file)) << file;
    }
  }
  const auto shown = numbers(r.output, "scan:");
  const auto report = nlohmann::ordered_json::parse(slurp(dir_ / "cli_outputs" / "report.json"));
  const auto written = numbers(polarform::report_lines(report, "scan_cam."));
  int compared = 0;
  for (const auto& [key, value] : shown) {
    if (key.rfind("scan_cam.design.", 0) != 0) continue;
    ASSERT_TRUE(written.count(key)) << key;
    EXPECT_EQ(value, written.at(key)) << key;
    ++compared;
  }
  EXPECT_GE(compared, 10);
  // The cam workspace shows the recovered design: its segments and laws (the follower is the
  // default knife-edge here, so the laws are those that reproduce the knife-edge's motion).
  std::vector<std::string> warnings;
  const polarform::CamProject recovered =
      polarform::read_cam_project(dir_ / "cli_design.xml", warnings);
  const auto design = numbers(r.output, "design:");
  ASSERT_EQ(number(design, "segments"), static_cast<double>(recovered.cam.segments.size()))
      << r.output;
  for (std::size_t k = 0; k < recovered.cam.segments.size(); ++k) {
    if (recovered.cam.segments[k].kind != polarform::SegmentKind::Dwell) {
      EXPECT_EQ(design.at("report.segments." + std::to_string(k) + ".law"),
                polarform::motion_law_name(recovered.cam.segments[k].law));
    }
  }
  EXPECT_GT(number(design, "report.control_points"), 0) << "the recovered design converts";
}

TEST_F(StudioTest, ScriptedEditChangesTheReportedNumbers) {
  const StudioRun r = run_studio("--project '" + (kExamples / "cams" / "roller.xml").string() +
                                 "' --workspace cam --bench-frames 20 --size 1280x800");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto before = numbers(r.output, "before:"), after = numbers(r.output, "after:");
  EXPECT_NE(number(before, "boundary_1_deg"), number(after, "boundary_1_deg"));
  EXPECT_NE(number(before, "report.max_pressure_angle_deg"),
            number(after, "report.max_pressure_angle_deg"));
  EXPECT_NE(r.output.find("frame time: mean"), std::string::npos) << r.output;
  EXPECT_EQ(error_count(r.output), 0) << r.output;
}

TEST_F(StudioTest, VesselScriptedEditResolvesTheHead) {
  // The pressure raised by 50 %: the head is solved again and the membrane hoop stress, linear in
  // the pressure, rises by the same factor.
  const StudioRun r =
      run_studio("--project '" + (kExamples / "vessels" / "torispherical_100_6.xml").string() +
                 "' --workspace vessel --bench-frames 10 --size 1280x800");
  ASSERT_EQ(r.status, 0) << r.output;
  const auto before = numbers(r.output, "before:"), after = numbers(r.output, "after:");
  const char* pressure = "report.vessel.pressure_mpa";
  const char* hoop = "report.stresses.head.max_hoop_stress_mpa";
  EXPECT_NEAR(number(after, pressure) / number(before, pressure), 1.5, 1e-12);
  EXPECT_NEAR(number(after, hoop) / number(before, hoop), 1.5, 1e-3);
  EXPECT_EQ(number(after, "solved"), 1);
  EXPECT_EQ(error_count(r.output), 0) << r.output;
}

TEST_F(StudioTest, BrokenProjectIsReportedAndTheSessionGoesOn) {
  const fs::path broken =
      write("broken.xml", "<polarform version=\"1\"><cam type=\"plate\" base-radius=\"40\"");
  const fs::path png = dir_ / "broken.png";
  const StudioRun r = run_studio("--project '" + broken.string() + "' --screenshot '" +
                                 png.string() + "' --size 1280x800");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(error_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("broken.xml"), std::string::npos) << "the message names the file";
  const PixelStats s = pixel_stats(png);  // the app still drew its workspace (the template picker)
  EXPECT_EQ(s.width, 1280);
  EXPECT_GT(s.colours, 50u);
}

TEST_F(StudioTest, InfeasibleDesignIsReportedAndTheSessionGoesOn) {
  // The rise and the return do not cancel: CamProgram refuses it.
  const fs::path bad = write("unbalanced.xml", R"(<polarform version="1">
  <cam type="plate" follower="roller" base-radius="40" roller-radius="10" rpm="300">
    <segment kind="rise" law="cycloidal" lift="20" to="180"/>
    <segment kind="return" law="cycloidal" lift="15" to="360"/>
  </cam>
</polarform>
)");
  const fs::path png = dir_ / "unbalanced.png";
  const StudioRun r = run_studio("--project '" + bad.string() + "' --workspace cam --screenshot '" +
                                 png.string() + "' --size 1280x800");
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_GE(error_count(r.output), 1) << r.output;
  EXPECT_EQ(number(numbers(r.output), "valid"), 0) << r.output;
  EXPECT_GT(pixel_stats(png).colours, 50u);
}

// A --script drives the cam workspace through the code of its menus: an edit, undo and redo give
// back exactly the numbers they should, Save as writes the edited project, and every item of
// File ▸ Export writes a file whose numbers match what the app reports.
TEST_F(StudioTest, ScriptEditsUndoesSavesAndExportsTheCam) {
  const fs::path script = write("session.txt", R"(numbers before
edit
numbers edited
undo
numbers undone
redo
numbers redone
save-as "saved cam.xml"
export iges out.igs
export step out.stp
export dxf out.dxf
export x3d out.x3d
export csv out.csv
export all all
)");
  const StudioRun r = run_studio("--project '" + (kExamples / "cams" / "roller.xml").string() +
                                 "' --script '" + script.string() + "' --size 1280x800");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(error_count(r.output), 0) << r.output;
  const auto before = numbers(r.output, "before:"), edited = numbers(r.output, "edited:");
  const auto undone = numbers(r.output, "undone:"), redone = numbers(r.output, "redone:");
  // The scripted edit drags the end of the first segment from 90° back to 45°.
  EXPECT_EQ(number(before, "boundary_1_deg"), 90);
  EXPECT_EQ(number(edited, "boundary_1_deg"), 45);
  for (const char* key : {"boundary_1_deg", "report.max_pressure_angle_deg",
                          "report.control_points", "report.max_radial_error_mm"}) {
    EXPECT_EQ(undone.at(key), before.at(key)) << key;
    EXPECT_EQ(redone.at(key), edited.at(key)) << key;
  }
  EXPECT_NE(edited.at("report.max_pressure_angle_deg"), before.at("report.max_pressure_angle_deg"));

  // Save as: the edited design, read back.
  std::vector<std::string> warnings;
  const polarform::CamProject saved = polarform::read_cam_project(dir_ / "saved cam.xml", warnings);
  ASSERT_EQ(saved.cam.segments.size(), 4u);
  EXPECT_NEAR(saved.cam.segments[1].start, std::numbers::pi / 4, 1e-12);
  EXPECT_NEAR(saved.cam.segments[0].end, std::numbers::pi / 4, 1e-12);

  // The exports: the NURBS profile the app measured, in every format.
  const double control_points = number(redone, "report.control_points");
  EXPECT_EQ(iges_curve_control_points(dir_ / "out.igs"), control_points);
  EXPECT_EQ(slurp(dir_ / "out.stp").rfind("ISO-10303-21;", 0), 0u);
  EXPECT_NE(slurp(dir_ / "out.stp").find("B_SPLINE_CURVE_WITH_KNOTS"), std::string::npos);
  EXPECT_NE(slurp(dir_ / "out.dxf").find("SPLINE"), std::string::npos);
  EXPECT_NE(slurp(dir_ / "out.x3d").find("<X3D"), std::string::npos);
  const auto svaj = csv_columns(dir_ / "out.csv");  // svaj.csv: θ, s, v, a, j, s', s'', s''', φ, …
  ASSERT_EQ(svaj.size(), 11u);
  EXPECT_NEAR(*std::max_element(svaj[1].begin(), svaj[1].end()), 20.0, 1e-9);  // the stroke
  double pressure = 0;
  for (double p : svaj[8]) pressure = std::max(pressure, std::abs(p));
  EXPECT_LE(pressure, number(redone, "report.max_pressure_angle_deg") + 1e-9);
  EXPECT_GT(pressure, number(redone, "report.max_pressure_angle_deg") - 0.5);  // 0.5° sampling
  // All outputs: what `polarform cam` writes, its report agreeing with the app, and each single
  // export byte for byte the file of the same bundle.
  const auto report = nlohmann::json::parse(slurp(dir_ / "all" / "report.json"));
  EXPECT_EQ(report["control_points"].get<double>(), control_points);
  EXPECT_EQ(report["max_radial_error_mm"].get<double>(),
            number(redone, "report.max_radial_error_mm"));
  for (const auto& [single, bundled] :
       {std::pair{"out.igs", "profile.igs"}, std::pair{"out.stp", "profile.stp"},
        std::pair{"out.dxf", "profile.dxf"}, std::pair{"out.x3d", "profile.x3d"},
        std::pair{"out.csv", "svaj.csv"}})
    EXPECT_EQ(slurp(dir_ / single), slurp(dir_ / "all" / bundled)) << single;
  for (const char* file : {"profile.igs", "profile.stp", "profile.dxf", "profile.x3d",
                           "svaj.csv", "svaj.svg", "report.html"})
    EXPECT_TRUE(fs::exists(dir_ / "all" / file)) << file;
  // The saved project through `polarform cam` gives the same report (but for its timing) and
  // the same bytes in every other file.
  const std::string cli = (fs::path(POLARFORM_BINARY_DIR) / "ui" / "cli" / "polarform").string();
  ASSERT_EQ(std::system(("SOURCE_DATE_EPOCH=1700000000 '" + cli + "' cam '" +
                         (dir_ / "saved cam.xml").string() + "' --out '" + (dir_ / "cli").string() +
                         "' -q 2>/dev/null")
                            .c_str()),
            0);
  auto cli_report = nlohmann::json::parse(slurp(dir_ / "cli" / "report.json"));
  auto app_report = report;
  cli_report.erase("seconds");
  app_report.erase("seconds");
  EXPECT_EQ(cli_report, app_report);
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(dir_ / "cli")) {
    const std::string file = entry.path().filename().string();
    if (file == "report.json") continue;
    EXPECT_EQ(slurp(entry.path()), slurp(dir_ / "all" / file)) << file;
    ++compared;
  }
  EXPECT_EQ(compared, 11);
}

// Files dropped on the window open in the workspace they belong to; a broken one is a message and
// the session goes on with the document it had. The fit's outputs are exported from the studio.
TEST_F(StudioTest, ScriptDropsFilesOnTheWindow) {
  std::ostringstream cloud;
  std::mt19937 rng(3);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (int i = 0; i < 4000; ++i) {
    Eigen::Vector3d p(gauss(rng), gauss(rng), gauss(rng));
    p = 25.0 * p.normalized();
    cloud << p.x() << ' ' << p.y() << ' ' << 0.9 * p.z() << '\n';
  }
  const fs::path scan = write("dropped.xyz", cloud.str());
  const fs::path broken = write("broken.xml", "<polarform version=\"1\"><cam");
  const fs::path script = write("drop.txt", "drop dropped.xyz\nnumbers dropped\n"
                                            "drop broken.xml\nnumbers after\n"
                                            "export all fit_outputs\n");
  const StudioRun r = run_studio("--project '" + (kExamples / "cams" / "roller.xml").string() +
                                 "' --script '" + script.string() + "' --size 1280x800");
  EXPECT_EQ(r.status, 1) << "the broken file is a failed action: " << r.output;
  EXPECT_EQ(error_count(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("broken.xml"), std::string::npos) << r.output;
  const auto dropped = numbers(r.output, "dropped:"), after = numbers(r.output, "after:");
  EXPECT_EQ(number(dropped, "points"), 4000);  // the fit workspace took the cloud
  EXPECT_EQ(number(dropped, "fitted"), 1);
  EXPECT_LT(number(dropped, "report.error_mm.rms"), 1e-2);  // a noise-free ellipsoid
  EXPECT_EQ(after, dropped) << "the broken file changed the fit workspace";
  const auto report = nlohmann::json::parse(slurp(dir_ / "fit_outputs" / "report.json"));
  EXPECT_EQ(report["error_mm"]["rms"].get<double>(), number(dropped, "report.error_mm.rms"))
      << report.dump(1);
  EXPECT_EQ(report["fairness"], "relative");  // the studio's defaults, as polarform fit's
  EXPECT_EQ(report["base"], "rqb");
  EXPECT_TRUE(fs::exists(dir_ / "fit_outputs" / "surface.igs"));
  EXPECT_TRUE(fs::exists(dir_ / "fit_outputs" / "deviation.ply"));
}

// The vessel workspace from a template: an edit re-solves the head, undo brings back the numbers
// bit for bit, and All outputs writes what `polarform vessel` writes.
TEST_F(StudioTest, ScriptDrivesTheVesselWorkspace) {
  const fs::path script = write("vessel.txt", R"(template vessel torispherical_100_6
numbers solved
edit
numbers edited
undo
numbers undone
export all vessel_outputs
save
workspace study
edit
)");
  const StudioRun r = run_studio("--script '" + script.string() + "' --size 1280x800");
  EXPECT_EQ(r.status, 1) << r.output;  // the last lines: two failed actions
  EXPECT_EQ(error_count(r.output), 2) << r.output;
  EXPECT_NE(r.output.find("line 8: torispherical_100_6 (new) has no file yet: use save-as PATH"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("line 10: the study workspace has nothing a script can edit"),
            std::string::npos)
      << r.output;
  const auto solved = numbers(r.output, "solved:"), edited = numbers(r.output, "edited:");
  const auto undone = numbers(r.output, "undone:");
  const char* pressure = "report.vessel.pressure_mpa";
  const char* hoop = "report.stresses.head.max_hoop_stress_mpa";
  EXPECT_NEAR(number(edited, pressure) / number(solved, pressure), 1.5, 1e-12);
  EXPECT_EQ(undone.at(pressure), solved.at(pressure));
  EXPECT_EQ(undone.at(hoop), solved.at(hoop));
  for (const char* file : {"profile.igs", "head.stp", "vessel.stp", "stress.svg", "report.json"})
    EXPECT_TRUE(fs::exists(dir_ / "vessel_outputs" / file)) << file;
}

// The project's compaction is the studio's: the roller refitted by default (the product's 110
// control points to 23, report.json's steps "product" → "refit"), left as the product with
// compaction="none".
TEST_F(StudioTest, TheProjectsCompactionDecidesTheProfile) {
  std::string none = slurp(kExamples / "cams" / "roller.xml");
  const auto at = none.find("<conversion ");
  ASSERT_NE(at, std::string::npos);
  none.insert(at + 12, "compaction=\"none\" ");
  const fs::path project = write("roller_none.xml", none);
  const fs::path script = write("numbers.txt", "numbers cam\n");
  for (const auto& [path, steps, points] :
       {std::tuple{kExamples / "cams" / "roller.xml", "refit", 23},
        {project, "knot removal", 110}}) {
    SCOPED_TRACE(path.string());
    const StudioRun r = run_studio("--project '" + path.string() + "' --script '" +
                                   script.string() + "' --size 1280x800");
    ASSERT_EQ(r.status, 0) << r.output;
    const auto cam = numbers(r.output, "cam:");
    EXPECT_EQ(number(cam, "report.control_points"), points);
    EXPECT_EQ(number(cam, "report.control_points_steps.0.control_points"), 110);
    EXPECT_EQ(cam.at("report.control_points_steps.1.step"), steps);
  }
}

// The last project, the workspace and the layout survive a restart (--state-dir keeps the state
// of headless runs, as ~/.config/polarform-studio keeps the desktop's).
TEST_F(StudioTest, StateIsKeptBetweenRuns) {
  const fs::path state = dir_ / "state";
  fs::create_directories(state);
  write("state/state.ini", "layout.cam.left=0.42\n");
  const fs::path first = write("first.txt", "edit\nsave-as edited.xml\nworkspace study\n");
  const StudioRun r1 = run_studio("--project '" + (kExamples / "cams" / "roller.xml").string() +
                                  "' --script '" + first.string() + "' --state-dir '" +
                                  state.string() + "' --size 1280x800");
  ASSERT_EQ(r1.status, 0) << r1.output;
  const std::string ini = slurp(state / "state.ini");
  EXPECT_NE(ini.find("last_project=" + (dir_ / "edited.xml").string()), std::string::npos) << ini;
  EXPECT_NE(ini.find("workspace=study"), std::string::npos) << ini;
  EXPECT_NE(ini.find("layout.cam.left=0.42\n"), std::string::npos) << ini;
  EXPECT_TRUE(fs::exists(state / "imgui.ini"));

  // No project on the command line: the edited one comes back, in the study workspace.
  const fs::path second = write("second.txt", "numbers restored\nworkspace cam\nnumbers cam\n");
  const StudioRun r2 = run_studio("--script '" + second.string() + "' --state-dir '" +
                                  state.string() + "' --size 1280x800");
  ASSERT_EQ(r2.status, 0) << r2.output;
  EXPECT_EQ(number(numbers(r2.output, "restored:"), "studied"), 1) << r2.output;
  EXPECT_EQ(number(numbers(r2.output, "cam:"), "boundary_1_deg"), 45) << r2.output;
  EXPECT_NE(slurp(state / "state.ini").find("layout.cam.left=0.42"), std::string::npos);
}

// A script that does not parse is refused as a whole, naming its file and line: exit code 2 and
// nothing of it done.
TEST_F(StudioTest, BadScriptIsRefusedBeforeAnythingRuns) {
  const fs::path script = write("bad.txt", "save-as first.xml\nexport iges\n");
  const StudioRun r = run_studio("--project '" + (kExamples / "cams" / "roller.xml").string() +
                                 "' --script '" + script.string() + "' --size 1280x800");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(script.string() + ":2: export takes 2 argument(s), got 1"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir_ / "first.xml"));
}

// The fit workspace's options are its document: an edit (a coarser net) fits again, undo restores
// the options (the fit shown stays until the next fit), and Save as writes them with the frame
// origin the project set.
TEST_F(StudioTest, ScriptEditsUndoesAndSavesAFitProject) {
  const fs::path project = write("fit.xml", R"(<polarform version="1">
  <fit scan=")" + (kExamples / "scans" / "sphere_like.xyz").string() +
                                                R"(" method="spherical" closed="yes" pole="g1"
       degree="3,3" ctrl="12,24" center="0.01,0,0"/>
</polarform>
)");
  const fs::path script = write("fit.txt", "numbers opened\nedit\nnumbers edited\nundo\n"
                                           "numbers undone\nsave-as saved_fit.xml\n");
  const StudioRun r = run_studio("--project '" + project.string() + "' --script '" +
                                 script.string() + "' --size 1280x800");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(error_count(r.output), 0) << r.output;
  const auto opened = numbers(r.output, "opened:"), edited = numbers(r.output, "edited:");
  const auto undone = numbers(r.output, "undone:");
  EXPECT_EQ(opened.at("net_setting"), "12x24");
  // Bicubic 12 x 24 times the RQB sphere: 35 x 81; 8 x 20: 3n − 1 along φ, 3n + 9 around θ.
  EXPECT_EQ(opened.at("report.control_net.nurbs.0") + "x" + opened.at("report.control_net.nurbs.1"),
            "35x81");
  EXPECT_EQ(edited.at("net_setting"), "8x20");
  EXPECT_EQ(edited.at("report.control_net.nurbs.0") + "x" + edited.at("report.control_net.nurbs.1"),
            "23x69");
  // A coarser net fits worse.
  EXPECT_GT(number(edited, "report.error_mm.rms"), number(opened, "report.error_mm.rms"));
  EXPECT_EQ(undone.at("net_setting"), "12x24");
  std::vector<std::string> warnings;
  const polarform::FitProject saved = polarform::read_fit_project(dir_ / "saved_fit.xml", warnings);
  EXPECT_EQ(saved.ctrl, std::make_pair(12, 24));
  ASSERT_TRUE(saved.center);
  EXPECT_EQ(*saved.center, Eigen::Vector3d(0.01, 0, 0));
  EXPECT_EQ(saved.pole, polarform::PoleTreatment::g1);
}

// One pipeline per job: for every example the studio opens — the cams, the vessels, the fit
// projects and the scans `polarform fit` takes, a planar profile among them — every report field
// the studio shows equals the CLI's report.json, and the studio's "All outputs" are the CLI's
// files byte for byte (timings aside; SOURCE_DATE_EPOCH fixes the exchange files' stamps).
TEST_F(StudioTest, EveryExampleShowsAndExportsWhatTheCliWrites) {
  struct Example {
    std::string command;  // the CLI command of its job
    fs::path file;
  };
  std::vector<Example> examples;
  for (const char* cam :
       {"roller", "flat_faced", "offset_roller", "polynomial", "cylindrical", "scca_dynamics",
        "oscillating_roller", "oscillating_flat_faced", "grooved", "conjugate"})
    examples.push_back({"cam", kExamples / "cams" / (std::string(cam) + ".xml")});
  for (const char* vessel :
       {"hemispherical", "ellipsoidal_2_1", "torispherical_100_6", "custom_curvature",
        "torispherical_100_6_exact", "minimum_stress_2_1_depth", "toriconical_30"})
    examples.push_back({"vessel", kExamples / "vessels" / (std::string(vessel) + ".xml")});
  for (const char* scan : {"sphere_like_fit.xml", "lobed_profile_fit.xml", "sphere_like.xyz",
                           "vase.xyz", "lobed_profile.xyz"})
    examples.push_back({"fit", kExamples / "scans" / scan});
  std::string script;
  for (std::size_t k = 0; k < examples.size(); ++k)
    script += "open \"" + examples[k].file.string() + "\"\nnumbers example" + std::to_string(k) +
              "\nexport all studio" + std::to_string(k) + "\n";
  const fs::path script_file = write("examples.txt", script);
  const StudioRun r =
      run_studio("--script '" + script_file.string() + "' --size 1280x800 --state-dir '" +
                 (dir_ / "state").string() + "'");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(error_count(r.output), 0) << r.output;
  const std::string cli = (fs::path(POLARFORM_BINARY_DIR) / "ui" / "cli" / "polarform").string();
  // Timings: the report.json fields and the report.html parts that measure the run, not the part.
  const auto without_timings = [](nlohmann::ordered_json j) {
    for (const char* field : {"seconds", "timings", "timings_s"}) j.erase(field);
    return j;
  };
  const auto html_without_timings = [](const std::string& html) {
    std::string out;
    std::istringstream in(html);
    bool stage_table = false;
    for (std::string line; std::getline(in, line);) {
      if (line.find("<th>stage</th><th>seconds</th>") != std::string::npos) stage_table = true;
      if (stage_table && line.find("</table>") != std::string::npos) stage_table = false;
      if (stage_table || line.find("<dt>time</dt>") != std::string::npos) continue;
      out += line + "\n";
    }
    return out;
  };
  for (std::size_t k = 0; k < examples.size(); ++k) {
    const Example& e = examples[k];
    SCOPED_TRACE(e.file.filename().string());
    const fs::path out = dir_ / ("cli" + std::to_string(k));
    ASSERT_EQ(std::system(("SOURCE_DATE_EPOCH=1700000000 '" + cli + "' " + e.command + " '" +
                           e.file.string() + "' --out '" + out.string() + "' -q 2>/dev/null")
                              .c_str()),
              0);
    const auto report = nlohmann::ordered_json::parse(slurp(out / "report.json"));
    // The numbers shown: each report field the studio prints is the CLI's, to the last digit.
    const auto shown = numbers(r.output, "example" + std::to_string(k) + ":");
    const auto written = numbers(polarform::report_lines(without_timings(report)));
    int compared = 0;
    for (const auto& [key, value] : shown) {
      if (key.rfind("report.", 0) != 0) continue;
      ASSERT_TRUE(written.count(key)) << key << " is not in report.json";
      EXPECT_EQ(value, written.at(key)) << key;
      ++compared;
    }
    EXPECT_GE(compared, 25) << "too few report fields shown";
    // The exports: every file of the CLI's bundle, the same bytes.
    const fs::path studio = dir_ / ("studio" + std::to_string(k));
    int files = 0;
    for (const auto& entry : fs::directory_iterator(out)) {
      const std::string name = entry.path().filename().string();
      ASSERT_TRUE(fs::exists(studio / name)) << name;
      if (name == "report.json")
        EXPECT_EQ(without_timings(nlohmann::ordered_json::parse(slurp(studio / name))),
                  without_timings(report));
      else if (name == "report.html")
        EXPECT_EQ(html_without_timings(slurp(studio / name)), html_without_timings(slurp(entry)));
      else
        EXPECT_TRUE(slurp(studio / name) == slurp(entry)) << name << " differs";
      ++files;
    }
    EXPECT_EQ(files, static_cast<int>(
                         std::distance(fs::directory_iterator(studio), fs::directory_iterator())));
  }
}

}  // namespace
