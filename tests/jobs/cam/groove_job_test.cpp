// The cam job's groove walls (cylindrical.xml asks for them with groove-depth): both walls are
// computed within the conversion tolerance, written to groove.igs (two entity-128 surfaces) and
// groove.stp, reported in report.json, and groove-depth round-trips through the project file and
// is rejected, with file, line and attribute, when negative or reaching the axis.
#include <gtest/gtest.h>

#include <cmath>

#include "jobs/report/report_number.h"
#include "src/error.h"
#include "tests/support/jobs/cam_job_support.h"

namespace polarform {
namespace {

using namespace cam_job_test;

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(GrooveJob, BothWallsMeetTheToleranceAgainstTheExactEnvelope) {
  const CamJobResult& r = example("cylindrical").result;
  ASSERT_EQ(track_of(r).groove.size(), 2u);
  const double tol = r.project().conversion.tolerance;
  for (const GrooveSurface& g : track_of(r).groove) {
    EXPECT_EQ(g.surface.front_v(), 52.0);  // cylinder-radius 60 ± groove-depth 16 / 2
    EXPECT_EQ(g.surface.back_v(), 68.0);
    EXPECT_LE(g.max_error, tol);
    // Exact wall points against the surface point of the same polar angle and radius.
    double worst = 0.0;
    for (int i = 0; i < 200; ++i)
      for (int j = 0; j < 20; ++j) {
        const Eigen::Vector3d w = std::get<BarrelCam>(r.design.cam)
                                      .groove_wall_point(2 * std::numbers::pi * (i + 0.43) / 200,
                                                         52.5 + 15.0 * j / 19, g.side);
        const double rho = std::hypot(w.x(), w.y());
        const Eigen::Vector3d s = g.surface.point(g.base.parameter(std::atan2(w.y(), w.x())), rho);
        worst = std::max(worst, (s - w).norm());
      }
    EXPECT_LE(worst, tol) << "side " << g.side;
  }
}

TEST(GrooveJob, FilesAndReportCarryBothWalls) {
  const ExampleRun& run = example("cylindrical");
  const std::string igs = slurp(run.dir / "groove.igs");
  int surfaces = 0;  // directory entries of type 128 (first of each entry's two lines)
  std::istringstream lines(igs);
  for (std::string line; std::getline(lines, line);)
    if (line.size() >= 73 && line[72] == 'D' && line.substr(0, 8) == "     128") ++surfaces;
  EXPECT_EQ(surfaces, 2 * 2);  // two lines per directory entry
  EXPECT_EQ(count(slurp(run.dir / "groove.stp"), "RATIONAL_B_SPLINE_SURFACE"), 2);
  const json j = read_json(run.dir / "report.json");
  ASSERT_TRUE(j.contains("groove"));
  EXPECT_EQ(j["groove"]["depth_mm"].get<double>(), 16.0);
  EXPECT_EQ(j["groove"]["tolerance_mm"].get<double>(), run.result.project().conversion.tolerance);
  ASSERT_EQ(j["groove"]["walls"].size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    const GrooveSurface& g = track_of(run.result).groove[k];
    const json& w = j["groove"]["walls"][k];
    EXPECT_EQ(w["degree_u"].get<int>(), g.surface.degree_u());
    EXPECT_EQ(w["degree_v"].get<int>(), g.surface.degree_v());
    EXPECT_EQ(w["control_points_u"].get<int>(), g.surface.size_u());
    EXPECT_EQ(w["control_points_v"].get<int>(), g.surface.size_v());
    EXPECT_EQ(w["max_error_mm"].get<double>(), report_number(g.max_error));
    EXPECT_LE(w["max_error_mm"].get<double>(), j["groove"]["tolerance_mm"].get<double>());
  }
  EXPECT_NE(slurp(run.dir / "report.html").find("Groove walls"), std::string::npos);
  // Plate cams are untouched.
  EXPECT_FALSE(read_json(example("roller").dir / "report.json").contains("groove"));
}

TEST(GrooveJob, GrooveDepthRoundTripsThroughTheProjectFile) {
  const CamProject p = load_example("cylindrical");
  EXPECT_EQ(p.cam.groove_depth, 16.0);
  const std::string xml = cam_project_xml(p);
  EXPECT_NE(xml.find("groove-depth=\"16\""), std::string::npos);
  std::vector<std::string> warnings;
  EXPECT_EQ(parse_cam_project(xml, "again.xml", warnings), p);
  EXPECT_TRUE(warnings.empty());
  CamProject none = p;
  none.cam.groove_depth = 0.0;
  EXPECT_EQ(cam_project_xml(none).find("groove-depth"), std::string::npos);
  EXPECT_EQ(parse_cam_project(cam_project_xml(none), "none.xml", warnings), none);
  EXPECT_TRUE(track_of(run_cam_job(none)).groove.empty());
}

TEST(GrooveJob, BadGrooveDepthNamesFileLineAndAttribute) {
  const std::string base = slurp(kExamples / "cylindrical.xml");
  const std::string cam_line =
      "bad.xml:" + std::to_string(1 + count(base.substr(0, base.find("<cam ")), "\n")) + ":";
  for (const char* bad : {"-4", "100", "118", "abc"}) {
    std::string xml = base;
    xml.replace(xml.find("groove-depth=\"16\""), 17, std::string("groove-depth=\"") + bad + "\"");
    std::vector<std::string> warnings;
    try {
      parse_cam_project(xml, "bad.xml", warnings);
      ADD_FAILURE() << "groove-depth " << bad << " accepted";
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(cam_line, 0), 0u) << message;
      EXPECT_NE(message.find("groove-depth"), std::string::npos) << message;
    }
  }
}

}  // namespace
}  // namespace polarform
