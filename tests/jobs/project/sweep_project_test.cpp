// Sweep project files: every field round-trips exactly; a minimal file takes the defaults and the
// job's options follow the project; each kind of bad value gives its own error naming file, line
// and attribute; unknown fields warn under the lenient policy.
#include "jobs/project/sweep_project.h"

#include <gtest/gtest.h>

#include "src/error.h"

namespace polarform {
namespace {

SweepProject parse(const std::string& xml, std::vector<std::string>* warnings = nullptr,
                   UnknownNames policy = UnknownNames::refuse) {
  std::vector<std::string> local;
  return parse_sweep_project(xml, "sweep.xml", warnings ? *warnings : local, policy);
}

std::string error_of(const std::string& attributes) {
  try {
    parse("<polarform version=\"1\">\n  <sweep " + attributes + "/>\n</polarform>\n");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SweepProject, EveryFieldRoundTripsExactly) {
  SweepProject p;
  p.scan = "meshes/part & co <1>.stl";
  p.kind = SweepKind::revolution;
  p.axis = Eigen::Vector3d(0.1 + 0.2, -1.0 / 3, 1);
  p.center = Eigen::Vector3d(1e-17, 123456.789, -4);
  p.tolerance = 0.1 + 0.2;
  p.degree = 5;
  p.corner_angle_deg = 1.0 / 7;
  p.skip_bad = true;
  const std::string xml = sweep_project_xml(p);
  EXPECT_EQ(parse(xml), p);
  EXPECT_EQ(sweep_project_xml(parse(xml)), xml);
}

TEST(SweepProject, MinimalFileTakesTheDefaults) {
  const SweepProject p = parse("<sweep scan=\"a.xyz\"/>");
  SweepProject expected;
  expected.scan = "a.xyz";
  EXPECT_EQ(p, expected);
  const SweepJobOptions o = sweep_job_options(p);
  EXPECT_EQ(o.kind, SweepKind::automatic);
  EXPECT_EQ(o.tolerance, 0.0);
  EXPECT_EQ(o.degree, 3);
  EXPECT_EQ(scan_path(p, "/data/projects/sweep.xml"), "/data/projects/a.xyz");
  const SweepJobOptions e =
      sweep_job_options(parse("<sweep scan=\"b.ply\" kind=\"extrusion\" axis=\"0,0,2\" "
                              "tolerance=\"0.02\" degree=\"2\" corner-angle=\"45\"/>"));
  EXPECT_EQ(e.kind, SweepKind::extrusion);
  EXPECT_EQ(*e.axis, Eigen::Vector3d(0, 0, 2));
  EXPECT_EQ(e.tolerance, 0.02);
  EXPECT_EQ(e.degree, 2);
  EXPECT_EQ(e.corner_angle_deg, 45);
  EXPECT_EQ(parse("<sweep scan=\"c.xyz\" kind=\"sections\"/>").kind, SweepKind::sections);
  EXPECT_STREQ(sweep_kind_word(SweepKind::sections), "sections");
}

TEST(SweepProject, BadValuesNameFileLineAndAttribute) {
  EXPECT_NE(error_of("").find("sweep.xml:2: <sweep> attribute 'scan'"), std::string::npos)
      << error_of("");
  EXPECT_NE(error_of("scan=\"a\" kind=\"trajectory\"").find("'kind'"), std::string::npos);
  EXPECT_NE(error_of("scan=\"a\" axis=\"0,0,0\"").find("'axis'"), std::string::npos);
  EXPECT_NE(error_of("scan=\"a\" axis=\"0,0\"").find("'axis'"), std::string::npos);
  EXPECT_NE(error_of("scan=\"a\" center=\"1,2,3\"").find("'center'"), std::string::npos);
  EXPECT_NE(
      error_of("scan=\"a\" kind=\"extrusion\" axis=\"0,0,1\" center=\"1,2,3\"").find("'center'"),
      std::string::npos);
  EXPECT_NE(error_of("scan=\"a\" tolerance=\"-1\"").find("'tolerance'"), std::string::npos);
  EXPECT_NE(error_of("scan=\"a\" degree=\"2.5\"").find("'degree'"), std::string::npos);
  EXPECT_NE(error_of("scan=\"a\" degree=\"1e10\"").find("'degree'"), std::string::npos);
  EXPECT_NE(error_of("scan=\"a\" corner-angle=\"180\"").find("'corner-angle'"), std::string::npos);
  EXPECT_NE(error_of("scan=\"a\" skip-bad=\"maybe\"").find("'skip-bad'"), std::string::npos);
  EXPECT_THROW(parse("<fit scan=\"a\"/>"), InputError);
}

TEST(SweepProject, UnknownFieldsWarnWhenLenient) {
  EXPECT_THROW(parse("<sweep scan=\"a\" colour=\"red\"/>"), InputError);
  std::vector<std::string> warnings;
  const SweepProject p = parse("<sweep scan=\"a\" colour=\"red\"/>", &warnings, UnknownNames::warn);
  EXPECT_EQ(p.scan, "a");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("colour"), std::string::npos);
}

}  // namespace
}  // namespace polarform
