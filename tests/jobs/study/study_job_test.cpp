// The study job on examples/cams/roller.xml over 1e-2:1e-4 mm (two steps per decade): study.csv
// has one row per tolerance with every method's measured error within it, the quartic base needs
// fewer control points than the RQB base, deviation.csv follows the power laws of DESIGN.md §4.3,
// and the plots and report.json are written.
#include "jobs/study/study_job.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/jobs/cam_job_support.h"
#include "tests/support/jobs/closed_forms.h"
#include "tests/support/jobs/study_run.h"

namespace polarform {
namespace {

using namespace cam_job_test;

TEST(StudyJob, StudyCsvHasOneRowPerToleranceWithinItsTolerance) {
  const Csv csv = read_csv(study().dir / "study.csv");
  // Without peers (study_peers_test.cpp has their columns).
  EXPECT_EQ(csv.header,
            (std::vector<std::string>{
                "tolerance [mm]", "quartic arcs", "quartic control points", "quartic degree",
                "quartic max radial error [mm]", "rqb arcs", "rqb control points", "rqb degree",
                "rqb max radial error [mm]", "cubic points", "cubic control points",
                "cubic max radial error [mm]", "exact arcs", "exact control points", "exact degree",
                "exact max radial error [mm]", "degree 3 control points",
                "degree 3 max radial error [mm]"}));
  const std::vector<double> tolerances = {1e-2, 3.16227766017e-3, 1e-3, 3.16227766017e-4, 1e-4};
  ASSERT_EQ(csv.rows.size(), tolerances.size());
  for (std::size_t k = 0; k < csv.rows.size(); ++k) {
    const std::vector<double>& row = csv.rows[k];
    SCOPED_TRACE(row[0]);
    EXPECT_NEAR(row[0], tolerances[k], 1e-15);
    for (std::size_t error :
         {csv.column("quartic max radial error [mm]"), csv.column("rqb max radial error [mm]"),
          csv.column("cubic max radial error [mm]")}) {
      EXPECT_LE(row[error], row[0]);
      EXPECT_GT(row[error], 0.0);
    }
    EXPECT_EQ(row[csv.column("quartic degree")], 9);  // deg F + 4
    EXPECT_EQ(row[csv.column("rqb degree")], 7);      // deg F + 2
    EXPECT_LT(row[csv.column("quartic control points")], row[csv.column("rqb control points")]);
    EXPECT_GT(row[csv.column("cubic points")], 0);
    if (k > 0) {  // tightening never needs fewer arcs or control points
      for (const char* count : {"quartic arcs", "quartic control points", "rqb arcs",
                                "rqb control points", "cubic control points"})
        EXPECT_GE(row[csv.column(count)], csv.rows[k - 1][csv.column(count)]) << count;
    }
  }
  // The table is the job's result.
  const StudyJobResult& r = study().result;
  ASSERT_EQ(r.rows.size(), csv.rows.size());
  for (std::size_t k = 0; k < r.rows.size(); ++k) {
    EXPECT_EQ(csv.rows[k][2], r.rows[k].quartic.control_points);
    EXPECT_EQ(csv.rows[k][4], r.rows[k].quartic.max_radial_error);
    EXPECT_EQ(csv.rows[k][11], r.rows[k].cubic.max_radial_error);
  }
}

TEST(StudyJob, DeviationCsvFollowsThePowerLaws) {
  const Csv csv = read_csv(study().dir / "deviation.csv");
  EXPECT_EQ(csv.header,
            (std::vector<std::string>{"arc angle [deg]", "rqb max angle deviation [rad]",
                                      "quartic minimax max angle deviation [rad]",
                                      "quartic printed max angle deviation [rad]"}));
  ASSERT_EQ(csv.rows.size(), 40u);
  EXPECT_NEAR(csv.rows.front()[0], 2, 1e-9);
  EXPECT_NEAR(csv.rows.back()[0], 180, 1e-9);
  for (const std::vector<double>& row : csv.rows) {
    const double phi = row[0] * kRadiansPerDegree / 2;          // half arc angle
    EXPECT_LE(row[1], 3.6697e-2 * std::pow(phi, 3)) << row[0];  // RQB
    EXPECT_LE(row[2], 1.1338e-4 * std::pow(phi, 5)) << row[0];  // quartic, minimax α
    EXPECT_LE(row[2], row[3]) << row[0];                        // minimax beats printed α
  }
  // DESIGN.md §4.3 table at 180°: RQB 1.42e-1, quartic minimax 1.08e-3 rad.
  EXPECT_NEAR(csv.rows.back()[1], 1.42e-1, 0.005e-1);
  EXPECT_NEAR(csv.rows.back()[2], 1.08e-3, 0.005e-3);
}

TEST(StudyJob, WritesPlotsAndReport) {
  const std::map<std::string, std::string> files = snapshot(study().dir.path());
  EXPECT_EQ(files.size(), 5u);
  for (const char* svg : {"study.svg", "deviation.svg"}) {
    ASSERT_TRUE(files.count(svg)) << svg;
    EXPECT_NE(files.at(svg).find("<svg"), std::string::npos) << svg;
    EXPECT_GT(files.at(svg).size(), 1000u) << svg;
  }
  const json report = read_json(study().dir / "report.json");
  EXPECT_EQ(report["command"], "study");
  EXPECT_EQ(report["design"], "roller");
  EXPECT_EQ(report["files"].get<std::vector<std::string>>(), study().files);
  ASSERT_EQ(report["rows"].size(), 5u);
  for (const json& row : report["rows"])
    for (const char* method : {"quasi_uniform", "rqb", "cubic_through_points"})
      EXPECT_LE(row[method]["max_radial_error_mm"].get<double>(),
                row["tolerance_mm"].get<double>());
}

}  // namespace
}  // namespace polarform
