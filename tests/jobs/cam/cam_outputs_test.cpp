// The cam job's files: every promised file exists, is non-empty and is listed in report.json (and
// nothing else is left in the directory); report.json parses and carries the documented fields with
// values that agree with the job and with closed forms; svaj.csv has unit-labelled headers and one
// row per half degree whose displacement and velocity equal the design's closed forms; two runs
// give identical files up to the time stamps the formats require and the measured run time.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <regex>
#include <set>

#include "jobs/report/report_number.h"
#include "tests/support/jobs/cam_job_support.h"
#include "tests/support/jobs/closed_forms.h"

namespace polarform {
namespace {

using namespace cam_job_test;

// companion: "groove_plate" (grooved.xml) or "conjugate" (conjugate.xml) for their three CAD files.
std::set<std::string> promised_files(bool plate, bool dynamics, const std::string& companion) {
  const std::string stem = plate ? "profile" : "track";
  std::set<std::string> files = {stem + ".igs", stem + ".stp", stem + ".dxf", stem + ".x3d",
                                 "profile.svg", "svaj.csv",    "svaj.svg",    "analysis.svg",
                                 "error.svg",   "report.json", "report.html"};
  if (plate) files.insert("profile_deg3.dxf");
  if (!plate) files.insert({"groove.igs", "groove.stp"});  // cylindrical.xml asks for the groove
  if (dynamics) files.insert({"force.svg", "torque.svg", "stress.svg"});  // scca_dynamics.xml
  if (!companion.empty())
    files.insert({companion + ".igs", companion + ".stp", companion + ".dxf"});
  return files;
}

TEST(CamOutputs, EveryPromisedFileExistsNonEmptyAndIsListed) {
  for (const std::string& name : kExampleNames) {
    const ExampleRun& run = example(name);
    const std::set<std::string> promised =
        promised_files(run.result.plate(), run.result.analysis.dynamics.has_value(),
                       name == "grooved"     ? "groove_plate"
                       : name == "conjugate" ? "conjugate"
                                             : "");
    const std::map<std::string, std::string> files = snapshot(run.dir.path());
    std::set<std::string> written;
    for (const auto& [file, content] : files) {
      written.insert(file);
      EXPECT_GT(content.size(), 100u) << name << "/" << file;
    }
    EXPECT_EQ(written, promised) << name;  // no temporary files left behind either
    EXPECT_EQ(std::set<std::string>(run.files.begin(), run.files.end()), promised) << name;
    const json report = read_json(run.dir / "report.json");
    EXPECT_EQ(report["files"].get<std::vector<std::string>>(), run.files) << name;
    for (const char* svg : {"svaj.svg", "analysis.svg", "profile.svg", "error.svg"})
      EXPECT_NE(files.at(svg).find("<svg"), std::string::npos) << name << "/" << svg;
    for (const char* svg : {"svaj.svg", "analysis.svg", "profile.svg", "error.svg"})
      EXPECT_NE(files.at("report.html").find(files.at(svg).substr(files.at(svg).find("<svg"), 200)),
                std::string::npos)
          << name << ": report.html embeds " << svg;
  }
}

TEST(CamOutputs, ReportCarriesTheIssueFieldsWithTheJobsNumbers) {
  for (const std::string& name : kExampleNames) {
    const ExampleRun& run = example(name);
    const CamJobResult& r = run.result;
    const json j = read_json(run.dir / "report.json");
    SCOPED_TRACE(name);
    EXPECT_EQ(j["command"], "cam");
    EXPECT_FALSE(j["polarform_version"].get<std::string>().empty());
    // The tolerance the profile was converted at: the project's, a conjugate pair's share of it.
    EXPECT_EQ(j["tolerance_mm"].get<double>(),
              r.project().conversion.tolerance *
                  (r.project().cam.conjugate ? kConjugateToleranceShare : 1.0));
    EXPECT_EQ(j["max_radial_error_mm"].get<double>(),
              report_number(r.conversion.conversion.max_radial_error));
    EXPECT_EQ(j["max_normal_error_mm"].get<double>(),
              report_number(r.conversion.conversion.max_normal_error));
    EXPECT_LE(j["max_radial_error_mm"].get<double>(), j["tolerance_mm"].get<double>());
    EXPECT_LE(j["max_normal_error_mm"].get<double>(), j["tolerance_mm"].get<double>());
    EXPECT_GT(j["max_radial_error_mm"].get<double>(), 0.0);
    const int degree = r.plate() ? plate_profile(r).curve.degree() : track_of(r).curve.degree();
    const int points = r.plate() ? plate_profile(r).curve.size() : track_of(r).curve.size();
    EXPECT_EQ(j["degree"].get<int>(), degree);
    EXPECT_EQ(j["control_points"].get<int>(), points);
    EXPECT_EQ(j["knot_count"].get<int>(), points + degree + 1);
    EXPECT_EQ(j["base"], "quasi-uniform");
    EXPECT_EQ(j["alpha"], "minimax");
    EXPECT_EQ(j["undercut"], false);
    EXPECT_GE(j["seconds"].get<double>(), 0.0);

    // Arcs: count, a full turn, and the worst arc is the reported maximum.
    ASSERT_EQ(j["arcs"].get<std::size_t>(), j["arc_list"].size());
    EXPECT_EQ(j["arcs"].get<std::size_t>(), r.conversion.conversion.arcs.size());
    double sweep = 0, worst = 0;
    for (const json& arc : j["arc_list"]) {
      sweep += arc["sweep_deg"].get<double>();
      worst = std::max(worst, arc["max_radial_error_mm"].get<double>());
      EXPECT_GE(arc["start_deg"].get<double>(), 0.0);
      EXPECT_LT(arc["start_deg"].get<double>(), 360.0);
    }
    EXPECT_NEAR(sweep, 360.0, 1e-9);
    EXPECT_EQ(worst, j["max_radial_error_mm"].get<double>());
    const json& budget = j["error_budget"];
    EXPECT_LE(budget["function_mm"].get<double>() + budget["synchronization_mm"].get<double>(),
              j["tolerance_mm"].get<double>() * (1 + 1e-12));

    // The design as read.
    const CamDesign& d = r.project().cam;
    EXPECT_EQ(j["cam"]["rpm"].get<double>(), d.rpm);
    EXPECT_EQ(j["cam"]["base_radius_mm"].get<double>(), d.base_radius);
    EXPECT_EQ(j["speed_rad_per_s"].get<double>(), report_number(2 * kPi * d.rpm / 60));
    ASSERT_EQ(j["segments"].size(), d.segments.size());
    EXPECT_EQ(j["segments"][0]["start_deg"].get<double>(), 0.0);
    EXPECT_NEAR(j["segments"].back()["end_deg"].get<double>(), 360.0, 1e-12);
    for (std::size_t k = 0; k < d.segments.size(); ++k)
      EXPECT_NEAR(j["segments"][k]["end_deg"].get<double>(), d.segments[k].end * kDegreesPerRadian,
                  1e-9);

    if (r.plate()) {
      EXPECT_EQ(j["cam"]["type"], "plate");
      EXPECT_EQ(j["max_pressure_angle_deg"].get<double>(),
                report_number(plate_analysis(r).max_pressure_angle.value * kDegreesPerRadian));
      EXPECT_EQ(j["min_radius_of_curvature_mm"].get<double>(),
                report_number(plate_analysis(r).min_convex_contour_radius.value));
      EXPECT_GT(j["min_radius_of_curvature_mm"].get<double>(), 0.0);
      EXPECT_TRUE(j["undercut_ranges_deg"].empty());
      const json& limited = j["degree_limited"];
      EXPECT_EQ(limited["degree"], 3);
      EXPECT_EQ(limited["control_points"].get<int>(), plate_profile(r).limited->curve.size());
      EXPECT_LE(limited["max_radial_error_mm"].get<double>(), j["tolerance_mm"].get<double>());
      EXPECT_FALSE(j.contains("exported_profile"));  // no max-degree in the examples
    } else {
      EXPECT_EQ(j["cam"]["type"], "cylindrical");
      EXPECT_EQ(j["cam"]["cylinder_radius_mm"].get<double>(), 60.0);
      EXPECT_FALSE(j.contains("degree_limited"));
    }
  }
}

TEST(CamOutputs, ReportedAnalysesEqualClosedForms) {
  // roller.xml: the 20 mm cycloidal rise over 90° has v_max = 2h/β at its middle (135°).
  const json roller = read_json(example("roller").dir / "report.json");
  EXPECT_NEAR(roller["motion"]["max_velocity"]["value_mm_per_rad"].get<double>(),
              2 * 20 / (kPi / 2), 1e-9);
  EXPECT_NEAR(roller["motion"]["max_velocity"]["at_deg"].get<double>(), 135, 1e-6);
  // a_max = 2π h/β² at a quarter of the rise (112.5°).
  EXPECT_NEAR(roller["motion"]["max_acceleration"]["value_mm_per_rad2"].get<double>(),
              2 * kPi * 20 / (kPi * kPi / 4), 1e-9);
  // cylindrical.xml: 30 mm cycloidal rise over 135°, pitch radius 60: tan α_max = (2h/β) / Rc.
  const json barrel = read_json(example("cylindrical").dir / "report.json");
  EXPECT_NEAR(barrel["max_pressure_angle_deg"].get<double>(),
              std::atan(2 * 30 / (135 * kRadiansPerDegree) / 60) * kDegreesPerRadian, 1e-9);
}

// The largest level a design reaches: the running sum of its rises and returns.
double stroke_of(const CamDesign& d) {
  double level = 0, top = 0;
  for (const SegmentSpec& s : d.segments) {
    level += s.kind == SegmentKind::Rise ? s.lift : s.kind == SegmentKind::Return ? -s.lift : 0;
    top = std::max(top, level);
  }
  return top;
}

TEST(CamOutputs, SvajCsvCoversTheRevolutionWithTheDesignsDisplacement) {
  for (const std::string& name : kExampleNames) {
    const ExampleRun& run = example(name);
    SCOPED_TRACE(name);
    const Csv csv = read_csv(run.dir / "svaj.csv");
    // An oscillating follower's motion is the arm's swing, in degrees.
    const std::string u = is_oscillating(run.result.project().cam.follower.kind) ? "deg" : "mm";
    std::vector<std::string> header = {"cam angle theta [deg]",
                                       "s [" + u + "]",
                                       "v [" + u + "/s]",
                                       "a [" + u + "/s^2]",
                                       "j [" + u + "/s^3]",
                                       "ds/dtheta [" + u + "/rad]",
                                       "d2s/dtheta2 [" + u + "/rad^2]",
                                       "d3s/dtheta3 [" + u + "/rad^3]"};
    if (run.result.plate()) {
      header.insert(header.end(), {"pressure angle [deg]", "contour radius of curvature [mm]",
                                   "pitch radius of curvature [mm]"});
    } else {
      header.push_back("pressure angle at pitch radius [deg]");
    }
    EXPECT_EQ(csv.header, header);
    ASSERT_EQ(csv.rows.size(), 720u);
    const double omega = 2 * kPi * run.result.project().cam.rpm / 60;
    double top = 0, bottom = INFINITY;
    for (std::size_t k = 0; k < csv.rows.size(); ++k) {
      const std::vector<double>& row = csv.rows[k];
      EXPECT_NEAR(row[0], 0.5 * k, 1e-9);
      top = std::max(top, row[1]);
      bottom = std::min(bottom, row[1]);
      EXPECT_NEAR(row[2], row[5] * omega, 1e-9 * (1 + std::abs(row[2])));          // v = s'ω
      EXPECT_NEAR(row[3], row[6] * omega * omega, 1e-9 * (1 + std::abs(row[3])));  // a = s''ω²
    }
    EXPECT_NEAR(top, stroke_of(run.result.project().cam), 1e-9);
    EXPECT_NEAR(bottom, 0.0, 1e-9);
  }
}

TEST(CamOutputs, SvajCsvOfTheRollerEqualsTheClosedForm) {
  const Csv csv = read_csv(example("roller").dir / "svaj.csv");
  const std::size_t s = csv.column("s [mm]"), ds = csv.column("ds/dtheta [mm/rad]"),
                    dds = csv.column("d2s/dtheta2 [mm/rad^2]");
  const std::size_t pitch = csv.column("pitch radius of curvature [mm]");
  for (const std::vector<double>& row : csv.rows) {
    const Motion m = roller_motion(row[0]);
    EXPECT_NEAR(row[s], m.s, 1e-9) << row[0];
    EXPECT_NEAR(row[ds], m.v, 1e-9) << row[0];
    EXPECT_NEAR(row[dds], m.a, 1e-9) << row[0];
    EXPECT_NEAR(row[pitch], polar_radius_of_curvature(50 + m.s, m.v, m.a), 1e-9) << row[0];
  }
}

// The file with the parts that legitimately change from run to run blanked: IGES Global time
// stamps, the STEP FILE_NAME time stamp and report.json's measured "seconds".
std::string without_run_stamps(const std::string& file, const std::string& text) {
  if (file.ends_with(".igs"))
    return std::regex_replace(text, std::regex(R"(15H\d{8}\.\d{6})"), "T");
  if (file.ends_with(".stp"))
    return std::regex_replace(text, std::regex(R"('\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ')"), "T");
  if (file == "report.json")
    return std::regex_replace(text, std::regex(R"("seconds": [-+.eE0-9]+)"), "T");
  return text;
}

TEST(CamOutputs, TwoRunsGiveIdenticalFilesUpToTimeStamps) {
  for (const std::string& name : {std::string("roller"), std::string("cylindrical")}) {
    const ExampleRun again(name, name + "_again");
    const std::map<std::string, std::string> first = snapshot(example(name).dir.path());
    const std::map<std::string, std::string> second = snapshot(again.dir.path());
    ASSERT_EQ(first.size(), second.size()) << name;
    for (const auto& [file, text] : first) {
      const std::string& other = second.at(file);
      const bool stamped =
          file.ends_with(".igs") || file.ends_with(".stp") || file == "report.json";
      if (!stamped) {
        EXPECT_TRUE(text == other) << name << "/" << file << " differs between runs";
      }
      EXPECT_TRUE(without_run_stamps(file, text) == without_run_stamps(file, other))
          << name << "/" << file << " differs beyond its time stamps";
    }
  }
}

// With SOURCE_DATE_EPOCH every file but report.json (its timing) is the same bytes run after run.
TEST(CamOutputs, SourceDateEpochMakesTheBundleReproducible) {
  ::setenv("SOURCE_DATE_EPOCH", "1700000000", 1);
  const CamJobResult& r = example("roller").result;
  const auto first = render_cam_outputs(r), second = render_cam_outputs(run_cam_job(r.project()));
  ::unsetenv("SOURCE_DATE_EPOCH");
  ASSERT_EQ(first.size(), second.size());
  for (const auto& [file, text] : first) {
    if (file == "report.json") continue;
    EXPECT_TRUE(text == second.at(file)) << file;
  }
  EXPECT_NE(first.at("profile.igs").find("15H20231114.221320"), std::string::npos);
}

}  // namespace
}  // namespace polarform
