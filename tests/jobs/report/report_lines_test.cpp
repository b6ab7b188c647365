// The report helpers shared by the jobs: a report's fields as name=value lines (the studio's
// script mode prints them, tests compare them with report.json) and the bundle's file list.
#include "jobs/report/report_lines.h"

#include <gtest/gtest.h>

#include "jobs/report/output_files.h"

namespace polarform {
namespace {

TEST(ReportLines, NestedNamesJoinWithDotsAndNumbersReadBackExactly) {
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
            "report.max_radial_error_mm=0.30000000000000004\n"
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
