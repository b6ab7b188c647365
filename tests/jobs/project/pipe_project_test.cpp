// Pipe project files: every field round-trips exactly; a minimal file takes the defaults (clamped
// uniform knots on [0, 1], cubic) and the job's options follow the project; each kind of bad
// value gives its own error naming file, line and attribute; unknown fields warn leniently.
#include "jobs/project/pipe_project.h"

#include <gtest/gtest.h>

#include "src/error.h"

namespace polarform {
namespace {

PipeProject parse(const std::string& xml, std::vector<std::string>* warnings = nullptr,
                  UnknownNames policy = UnknownNames::refuse) {
  std::vector<std::string> local;
  return parse_pipe_project(xml, "pipe.xml", warnings ? *warnings : local, policy);
}

std::string error_of(const std::string& xml) {
  try {
    parse(xml);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const char* kFourPoints =
    "  <point at=\"0,0,0\"/>\n  <point at=\"1,2,0\"/>\n  <point at=\"2,-1,1\"/>\n"
    "  <point at=\"3,0,2\"/>\n";

TEST(PipeProject, EveryFieldRoundTripsExactly) {
  PipeProject p;
  p.degree = 2;
  p.points = {Eigen::Vector3d(0.1 + 0.2, -1.0 / 3, 1e-17), Eigen::Vector3d(123456.789, 4, -5),
              Eigen::Vector3d(7, 8, 9), Eigen::Vector3d(1, 1, 1)};
  p.weights = {1.0, 1.0 / 7, 2.5, 1.0};
  p.knots = {0, 0, 0, 1.0 / 3, 2, 2, 2};
  p.closure = SpineClosure::open;
  p.radius = 0.1 + 0.7;
  p.tolerance = 1e-5;
  p.frame = FrameRule::frenet;
  const std::string xml = pipe_project_xml(p);
  EXPECT_EQ(parse(xml), p);
  EXPECT_EQ(pipe_project_xml(parse(xml)), xml);
}

TEST(PipeProject, MinimalFileTakesTheDefaults) {
  const PipeProject p = parse(std::string("<pipe>\n") + kFourPoints + "</pipe>\n");
  EXPECT_EQ(p.degree, 3);
  EXPECT_EQ(p.weights, std::vector<double>(4, 1.0));
  EXPECT_TRUE(p.knots.empty());
  EXPECT_FALSE(p.radius.has_value());
  const NurbsCurve3d spine = pipe_spine(p);
  EXPECT_EQ(spine.knots(), (Knots{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(spine.control_point(2), Eigen::Vector3d(2, -1, 1));
  const PipeJobOptions o = pipe_job_options(p);
  EXPECT_EQ(o.radius, 0.0);
  EXPECT_EQ(o.tolerance, 0.0);
  EXPECT_EQ(o.frame, FrameRule::rmf);
  EXPECT_EQ(o.closure, SpineClosure::automatic);
  // Degree 2 on five points: one interior knot at 1/3 and 2/3 of [0, 1].
  const PipeProject q =
      parse(std::string("<polarform version=\"1\"><pipe degree=\"2\" radius=\"3\" "
                        "frame=\"fixed\" tol=\"0.01\" closed=\"no\">\n") +
            kFourPoints + "<point at=\"5,5,5\" weight=\"2\"/></pipe></polarform>");
  const NurbsCurve3d s = pipe_spine(q);
  ASSERT_EQ(s.knots().size(), 8u);
  EXPECT_DOUBLE_EQ(s.knots()[3], 1.0 / 3);
  EXPECT_DOUBLE_EQ(s.knots()[4], 2.0 / 3);
  EXPECT_EQ(s.weight(4), 2.0);
  const PipeJobOptions oq = pipe_job_options(q);
  EXPECT_EQ(oq.radius, 3.0);
  EXPECT_EQ(oq.tolerance, 0.01);
  EXPECT_EQ(oq.frame, FrameRule::fixed);
  EXPECT_EQ(oq.closure, SpineClosure::open);
}

TEST(PipeProject, BadValuesNameFileLineAndAttribute) {
  const auto pipe = [](const std::string& attributes, const std::string& points = kFourPoints) {
    return "<polarform version=\"1\">\n<pipe " + attributes + ">\n" + points +
           "</pipe>\n</polarform>\n";
  };
  EXPECT_EQ(error_of(pipe("radius=\"-1\"")),
            "pipe.xml:2: <pipe> attribute 'radius': expected a number > 0, got '-1'");
  EXPECT_EQ(
      error_of(pipe("frame=\"twisted\"")),
      "pipe.xml:2: <pipe> attribute 'frame': expected one of rmf|frenet|fixed, got 'twisted'");
  EXPECT_EQ(error_of(pipe("degree=\"2.5\"")),
            "pipe.xml:2: <pipe> attribute 'degree': expected an integer in [1, 9], got '2.5'");
  EXPECT_EQ(error_of(pipe("degree=\"4\"")),
            "pipe.xml:2: <pipe>: expected at least degree + 1 = 5 <point at=\"x,y,z\"/> elements, "
            "got 4");
  EXPECT_EQ(error_of(pipe("knots=\"0,0,0,0,1,1,1\"")),
            "pipe.xml:2: <pipe> attribute 'knots': expected 8 clamped, non-decreasing knots (7 "
            "given for 4 points of degree 3), got '0,0,0,0,1,1,1'");
  EXPECT_EQ(error_of(pipe("degree=\"2\" knots=\"0,0,0.5,0.6,1,1,1\"")),
            "pipe.xml:2: <pipe> attribute 'knots': expected 7 clamped, non-decreasing knots (the "
            "ends are not clamped), got '0,0,0.5,0.6,1,1,1'");
  EXPECT_EQ(error_of(pipe("degree=\"1\" knots=\"0,0,0.5,0.5,1,1\"")),
            "pipe.xml:2: <pipe> attribute 'knots': expected 6 clamped, non-decreasing knots (knot "
            "0.5 repeats 2 times, at most the degree inside), got '0,0,0.5,0.5,1,1'");
  EXPECT_EQ(error_of(pipe("degree=\"2\" knots=\"0,0,0,0.7,0.6,1,1\"")),
            "pipe.xml:2: <pipe> attribute 'knots': expected 7 clamped, non-decreasing knots (knot "
            "4 decreases), got '0,0,0,0.7,0.6,1,1'");
  EXPECT_EQ(error_of(pipe("knots=\"0,x\"")),
            "pipe.xml:2: <pipe> attribute 'knots': expected comma-separated numbers, got '0,x'");
  EXPECT_EQ(error_of(pipe("", "<point at=\"0,0\"/>")),
            "pipe.xml:3: <point> attribute 'at': expected 3 comma-separated numbers, got '0,0'");
  EXPECT_EQ(error_of(pipe("", "<point at=\"0,0,0\" weight=\"0\"/>")),
            "pipe.xml:3: <point> attribute 'weight': expected a number > 0, got '0'");
  EXPECT_EQ(error_of("<sweep scan=\"a\"/>"),
            "pipe.xml:1: <sweep>: expected a <polarform> or <pipe> root element");
}

TEST(PipeProject, UnknownNamesAreRefusedOrWarned) {
  const std::string xml = std::string("<pipe radius=\"1\" colour=\"red\">\n") + kFourPoints +
                          "  <point at=\"4,0,0\" size=\"2\"/>\n</pipe>\n";
  EXPECT_NE(error_of(xml).find("unknown attribute 'colour' on <pipe>"), std::string::npos)
      << error_of(xml);
  std::vector<std::string> warnings;
  const PipeProject p = parse(xml, &warnings, UnknownNames::warn);
  EXPECT_EQ(p.points.size(), 5u);
  EXPECT_EQ(warnings.size(), 2u);
}

}  // namespace
}  // namespace polarform
