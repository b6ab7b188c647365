// The report helpers shared by the jobs: a report's fields as name=value lines (the studio's
// script mode prints them, tests compare them with report.json) and the bundle's file list.
#include "jobs/report/report_lines.h"

#include <gtest/gtest.h>

#include <cmath>

#include "jobs/report/output_files.h"
#include "jobs/report/report_number.h"

namespace polarform {
namespace {

TEST(ReportLines, NestedNamesJoinWithDotsAndNumbersAsReportJsonStatesThem) {
  const nlohmann::ordered_json fields = {
      {"arcs", 6},
      {"max_radial_error_mm", 0.1 + 0.2},
      {"base", "rqb"},
      {"undercut", false},
      {"min_concave_radius_of_curvature_mm", nullptr},
      {"motion", {{"max_velocity", {{"value_mm_per_rad", 1e-300}, {"at_deg", 135.0}}}}},
      {"arc_list", {{{"start_deg", 0.0}}, {{"start_deg", 90.5}}}},
      {"warnings", nlohmann::ordered_json::array()}};
  EXPECT_EQ(report_lines(fields),
            "report.arcs=6\n"
            "report.max_radial_error_mm=0.3\n"
            "report.base=rqb\n"
            "report.undercut=false\n"
            "report.min_concave_radius_of_curvature_mm=null\n"
            "report.motion.max_velocity.value_mm_per_rad=1e-300\n"
            "report.motion.max_velocity.at_deg=135\n"
            "report.arc_list.0.start_deg=0\n"
            "report.arc_list.1.start_deg=90.5\n");
  EXPECT_EQ(report_lines({{"a", 1}}, ""), "a=1\n");
  EXPECT_EQ(report_lines({{"why", "two\nlines \\ one"}}, ""), "why=two\\nlines \\\\ one\n");
}

// Numbers are written as humans write them: 12 significant digits, so float noise from unit
// conversions disappears and every measured figure stays.
TEST(ReportNumber, TwelveSignificantDigits) {
  EXPECT_EQ(report_number(239.99999999999997), 240.0);
  EXPECT_EQ(report_number(0.1 + 0.2), 0.3);
  EXPECT_EQ(report_number(4.1887902047863905 * 180 / 3.141592653589793), 240.0);
  EXPECT_EQ(report_number(1.23456789012345e-9), 1.23456789012e-9);
  EXPECT_EQ(report_number(-987654.3210987654), -987654.321099);
  EXPECT_EQ(report_number(3.3e-10), 3.3e-10);
  EXPECT_EQ(report_number(1e-300), 1e-300);
  EXPECT_EQ(report_number(0.0), 0.0);
  EXPECT_TRUE(std::isinf(report_number(INFINITY)));
  const nlohmann::ordered_json j = {
      {"a", 239.99999999999997}, {"n", 7}, {"list", {0.1 + 0.2, "x"}}};
  EXPECT_EQ(report_json_text(j),
            "{\n  \"a\": 240.0,\n  \"n\": 7,\n  \"list\": [\n    0.3,\n    \"x\"\n  ]\n}\n");
}

TEST(OutputFiles, ReportsComeLastInTheirOrder) {
  const std::map<std::string, std::string> content = {
      {"svaj.csv", ""}, {"report.json", ""}, {"profile.igs", ""}, {"error.svg", ""}};
  EXPECT_EQ(report_file_list(content),
            (std::vector<std::string>{"error.svg", "profile.igs", "svaj.csv", "report.json",
                                      "report.html"}));
  EXPECT_EQ(report_file_list(content, {"report.json"}),
            (std::vector<std::string>{"error.svg", "profile.igs", "svaj.csv", "report.json"}));
}

}  // namespace
}  // namespace polarform
