// The files of the vessel job: every output exists with its format's header, report.json holds the
// documented fields with the job's numbers, the CSVs carry units, and a bad project or design
// leaves the output directory without new files.
#include "jobs/vessel/vessel_outputs.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "jobs/report/report_number.h"
#include "jobs/vessel/vessel_plots.h"
#include "src/error.h"
#include "tests/support/jobs/vessel_job_support.h"

namespace polarform {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;
using namespace vessel_job_test;

const std::set<std::string> kFiles = {
    "curvature.svg", "head.igs",    "head.stp",    "profile.csv", "profile.dxf", "profile.igs",
    "profile.stp",   "profile.svg", "report.html", "report.json", "stress.csv",  "stress.svg",
    "vessel.stp"};

// What `polarform vessel` does: read, run, write.
std::vector<std::string> design_to(const std::filesystem::path& design,
                                   const std::filesystem::path& out) {
  std::vector<std::string> warnings;
  const VesselJobResult r = run_vessel_job(read_vessel_project(design, warnings));
  return write_vessel_outputs(r, out);
}

TEST(VesselOutputs, EveryFileWithItsFormatHeader) {
  const std::filesystem::path dir = scratch_dir("out");
  const std::vector<std::string> files = design_to(example("torispherical_100_6.xml"), dir);
  EXPECT_EQ(std::set<std::string>(files.begin(), files.end()), kFiles);
  EXPECT_EQ(files_in(dir), kFiles);  // and no temporary left behind
  for (const char* igs : {"profile.igs", "head.igs"}) {
    const std::string text = read_text(dir / igs);
    ASSERT_GE(text.size(), 81u) << igs;
    EXPECT_EQ(text[72], 'S') << igs;   // IGES fixed format: Start section, column 73
    EXPECT_EQ(text[80], '\n') << igs;  // 80-column lines
    EXPECT_THAT(text, HasSubstr(igs == std::string("head.igs") ? "128," : "126,")) << igs;
  }
  for (const char* stp : {"profile.stp", "head.stp", "vessel.stp"}) {
    const std::string text = read_text(dir / stp);
    EXPECT_THAT(text, StartsWith("ISO-10303-21;\nHEADER;\n")) << stp;
    EXPECT_THAT(text, HasSubstr("END-ISO-10303-21;")) << stp;
  }
  EXPECT_THAT(read_text(dir / "profile.stp"), HasSubstr("B_SPLINE_CURVE_WITH_KNOTS"));
  EXPECT_THAT(read_text(dir / "head.stp"), HasSubstr("OPEN_SHELL"));
  // Head, cylinder and far head share their circles: one closed shell.
  EXPECT_THAT(read_text(dir / "vessel.stp"), HasSubstr("CLOSED_SHELL"));
  const std::string dxf = read_text(dir / "profile.dxf");
  EXPECT_THAT(dxf, StartsWith("  0\nSECTION\n  2\nHEADER\n"));
  EXPECT_THAT(dxf, HasSubstr("SPLINE"));
  for (const char* svg : {"curvature.svg", "stress.svg", "profile.svg"})
    EXPECT_THAT(read_text(dir / svg), HasSubstr("<svg")) << svg;
  const std::string html = read_text(dir / "report.html");
  EXPECT_THAT(html, HasSubstr("polarform vessel report"));
  std::size_t figures = 0;
  for (std::size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1))
    ++figures;
  EXPECT_EQ(figures, 3u);
}

// Curvature is stated in 1/mm, the unit of every other length, in the HTML as in report.json.
TEST(VesselOutputs, HtmlStatesCurvatureInPerMillimetre) {
  const std::filesystem::path dir = scratch_dir("kappa");
  design_to(example("custom_curvature.xml"), dir);
  const std::string html = read_text(dir / "report.html");
  EXPECT_THAT(html, HasSubstr("target κ [1/mm]"));
  EXPECT_THAT(html, HasSubstr("achieved κ [1/mm]"));
  EXPECT_EQ(html.find("1/m]"), std::string::npos);
  EXPECT_EQ(html.find(" 1/m<"), std::string::npos);
}

TEST(VesselOutputs, CsvHeadersCarryUnitsAndRowsMatchTheSamples) {
  const std::filesystem::path dir = scratch_dir("out");
  design_to(example("ellipsoidal_2_1.xml"), dir);
  const std::string profile = read_text(dir / "profile.csv");
  EXPECT_THAT(profile, StartsWith("theta [deg],R [mm],dR/dtheta [mm/rad],d2R/dtheta2 [mm/rad^2],"
                                  "x [mm],z [mm],kappa [1/mm],"
                                  "preset R [mm],preset kappa [1/mm]\n"));
  EXPECT_EQ(std::count(profile.begin(), profile.end(), '\n'), 1 + 361);
  const std::string stress = read_text(dir / "stress.csv");
  EXPECT_THAT(stress, StartsWith("s [mm],theta [deg],rho [mm],z [mm],kappa1 [1/mm],r2 [mm],"
                                 "N_phi [N/mm],N_theta [N/mm],sigma_phi [MPa],sigma_theta [MPa],"
                                 "on cylinder [1/0]\n"));
  // One row per sample: 2 on the cylinder, the head's grid, its joints and located extremes.
  std::vector<std::string> warnings;
  const VesselSolveStage solved =
      solve_vessel_head(read_vessel_project(example("ellipsoidal_2_1.xml"), warnings));
  EXPECT_EQ(std::count(stress.begin(), stress.end(), '\n'),
            1 + static_cast<long>(solved.solution.stresses.samples.size()));
  EXPECT_GE(solved.solution.stresses.samples.size(), 2u + 181u);
  // The first cylinder sample: s = −length/2, σ_θ = pR/t = 100, σ_φ = pR/2t = 50.
  EXPECT_THAT(stress, HasSubstr("\n-750,0,500,-750,0,500,500,1000,50,100,1\n"));
}

TEST(VesselOutputs, ReportJsonHasTheDocumentedFields) {
  const std::filesystem::path dir = scratch_dir("out");
  const VesselProject project = load_example("hemispherical.xml");
  const VesselJobResult r = run_vessel_job(project);
  const std::vector<std::string> files = write_vessel_outputs(r, dir);
  const auto j = nlohmann::json::parse(read_text(dir / "report.json"));
  EXPECT_EQ(j["command"], "vessel");
  EXPECT_EQ(j["vessel"]["radius_mm"], 500.0);
  EXPECT_EQ(j["vessel"]["pressure_mpa"], 2.0);
  const auto& s = j["synthesis"];
  EXPECT_EQ(s["degree"], 5);
  EXPECT_EQ(s["ordinates"], 20);
  EXPECT_TRUE(s["targets_from_preset"].get<bool>());
  EXPECT_EQ(s["target_count"], 48);
  EXPECT_GT(s["iterations"].get<int>(), 0);
  EXPECT_EQ(s["iterations"], r.solved.solution.synthesis.iterations);
  EXPECT_LE(s["max_abs_residual_per_mm"].get<double>(), 1e-12);
  EXPECT_LE(s["rms_residual_per_mm"].get<double>(), s["max_abs_residual_per_mm"].get<double>());
  EXPECT_LE(s["max_violation"].get<double>(), 1e-9);
  EXPECT_NEAR(s["min_radius_mm"].get<double>(), 500.0, 1e-7);
  ASSERT_EQ(j["targets"].size(), 48u);
  EXPECT_NEAR(j["targets"][0]["theta_deg"].get<double>(), 180.0 / 96, 1e-12);
  EXPECT_NEAR(j["targets"][0]["target_per_mm"].get<double>(), 1 / 500.0, 1e-15);
  EXPECT_NEAR(j["targets"][0]["achieved_per_mm"].get<double>(), 1 / 500.0, 1e-12);
  ASSERT_EQ(j["conditions"].size(), 6u);  // the default R, R', R'' at both ends
  EXPECT_EQ(j["conditions"][0]["name"], "R(0)");
  EXPECT_EQ(j["conditions"][0]["unit"], "mm");
  EXPECT_EQ(j["conditions"][5]["name"], "R''(π)");
  EXPECT_EQ(j["conditions"][5]["unit"], "mm/rad^2");
  for (const auto& c : j["conditions"]) EXPECT_LE(std::abs(c["violation"].get<double>()), 1e-9);
  EXPECT_NEAR(j["head"]["depth_mm"].get<double>(), 500.0, 1e-7);
  EXPECT_NEAR(j["head"]["junction_curvature_per_mm"].get<double>(), 1 / 500.0, 1e-12);
  EXPECT_EQ(j["tolerance_mm"], 1e-3);
  EXPECT_EQ(j["max_radial_error_mm"], report_number(r.converted.conversion->max_radial_error));
  EXPECT_LE(j["max_radial_error_mm"].get<double>(), 1e-3);
  EXPECT_EQ(j["degree"], r.converted.conversion->curve.degree());  // the product C = F·B, refitted
  EXPECT_EQ(j["control_points"], r.converted.conversion->curve.size());
  EXPECT_EQ(j["arcs"], r.converted.conversion->arcs.size());
  EXPECT_EQ(j["arc_list"].size(), r.converted.conversion->arcs.size());
  EXPECT_TRUE(j["error_budget"]["function_exact"].get<bool>());
  EXPECT_EQ(j["surfaces"]["head"]["degree_u"], 2);  // a full turn of rational quadratic arcs
  EXPECT_EQ(j["surfaces"]["head"]["degree_v"], r.converted.conversion->curve.degree());
  EXPECT_EQ(j["surfaces"]["cylinder"]["degree_v"], 1);
  const auto& st = j["stresses"];
  EXPECT_NEAR(st["cylinder"]["hoop_stress_mpa"].get<double>(), 100.0, 1e-9);
  EXPECT_NEAR(st["cylinder"]["meridional_stress_mpa"].get<double>(), 50.0, 1e-9);
  EXPECT_NEAR(st["head"]["max_hoop_stress_mpa"].get<double>(), 50.0, 5e-8);
  EXPECT_NEAR(st["head"]["min_hoop_stress_mpa"].get<double>(), 50.0, 5e-8);
  EXPECT_NEAR(st["head"]["max_meridional_stress_mpa"].get<double>(), 50.0, 5e-8);
  EXPECT_NEAR(st["max_stress_mpa"].get<double>(), 100.0, 1e-9);
  EXPECT_FALSE(st["compressive_hoop"].get<bool>());
  EXPECT_TRUE(st["compressive_hoop_bands"].empty());
  const auto& preset = j["preset"];
  EXPECT_EQ(preset["kind"], "hemispherical");
  EXPECT_LE(preset["max_deviation_mm"].get<double>(), 1e-7);
  ASSERT_EQ(preset["curvature_jumps"].size(), 2u);  // the junctions: 0 → 1/R and back
  EXPECT_EQ(preset["curvature_jumps"][0]["kappa_before_per_mm"], 0.0);
  EXPECT_NEAR(preset["curvature_jumps"][0]["kappa_after_per_mm"].get<double>(), 1 / 500.0, 1e-15);
  EXPECT_TRUE(j["warnings"].empty());
  const auto& t = j["timings"];
  EXPECT_GT(t["total_s"].get<double>(), 0.0);
  EXPECT_GE(t["total_s"].get<double>(), t["solve_s"].get<double>() + t["convert_s"].get<double>() +
                                             t["revolve_s"].get<double>());
  EXPECT_EQ(j["files"].get<std::vector<std::string>>(), files);
}

TEST(VesselOutputs, CompressiveHoopStressIsFlagged) {
  const std::filesystem::path dir = scratch_dir("out");
  design_to(example("ellipsoidal_2_1.xml"), dir);
  const auto j = nlohmann::json::parse(read_text(dir / "report.json"));
  const auto& st = j["stresses"];
  EXPECT_TRUE(st["compressive_hoop"].get<bool>());
  ASSERT_EQ(st["compressive_hoop_bands"].size(), 1u);
  EXPECT_EQ(st["compressive_hoop_bands"][0]["theta_from_deg"], 0.0);
  EXPECT_NEAR(st["compressive_hoop_bands"][0]["min_hoop_stress_mpa"].get<double>(), -100.0, 1.0);
  EXPECT_NEAR(st["head"]["min_hoop_stress_mpa"].get<double>(), -100.0, 1.0);
  EXPECT_EQ(j["preset"]["stresses"]["compressive_hoop"], true);
  ASSERT_EQ(j["warnings"].size(), 1u);
  EXPECT_THAT(j["warnings"][0].get<std::string>(), HasSubstr("compressive hoop stress down to"));
  EXPECT_THAT(read_text(dir / "stress.svg"), HasSubstr("compressive hoop stress (design)"));
}

// The stress plot spends its width on the head (the cylinder's stresses are constant: a stub of
// 15 % of the head's meridian length), and the preset's compressive range is drawn apart from the
// design's band: lines at its ends in its own colour, never a second band on top.
TEST(VesselOutputs, StressPlotShowsTheHeadAndTellsTheCompressiveRangesApart) {
  std::vector<std::string> warnings;
  const VesselJobResult r =
      run_vessel_job(read_vessel_project(example("torispherical_100_6.xml"), warnings));
  const VesselSolution& s = r.solved.solution;
  ASSERT_TRUE(s.preset);
  const Figure f = stress_figure(r.solved);
  const Plot& plot = f.panels().front();
  double head = 0;
  for (const StressSample& k : s.stresses.samples) head = std::max(head, k.s);
  ASSERT_TRUE(plot.x_range);
  EXPECT_NEAR(plot.x_range->min, -0.15 * head, 1e-9);
  EXPECT_NEAR(plot.x_range->max, head, 1e-9);
  // Bands: the design's compressive ranges only.
  ASSERT_EQ(plot.bands().size(), s.stresses.compressive_hoop.size());
  for (std::size_t i = 0; i < plot.bands().size(); ++i) {
    EXPECT_EQ(plot.bands()[i].x0, s.stresses.compressive_hoop[i].s_from);
    EXPECT_EQ(plot.bands()[i].x1, s.stresses.compressive_hoop[i].s_to);
  }
  // The preset's: a line at each end, in a colour no band has.
  const std::vector<CompressiveBand>& preset = s.preset->stresses.compressive_hoop;
  ASSERT_FALSE(preset.empty());
  for (const CompressiveBand& b : preset)
    for (const double end : {b.s_from, b.s_to}) {
      const auto line = std::find_if(plot.vertical_lines().begin(), plot.vertical_lines().end(),
                                     [&](const ReferenceLine& l) { return l.value == end; });
      ASSERT_NE(line, plot.vertical_lines().end()) << end;
      for (const Band& band : plot.bands()) EXPECT_NE(line->color, band.color);
    }
}

TEST(VesselOutputs, BrokenProjectNamesTheLineAndWritesNothing) {
  const std::filesystem::path dir = scratch_dir("out");
  const std::filesystem::path bad = write_text(
      scratch_dir("in") / "bad.xml",
      vessel_xml("<head preset=\"torispherical\" crown=\"1000\" knuckle=\"-6\"/>"));
  try {
    design_to(bad, dir);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), StartsWith(bad.string() + ":3: <head> attribute 'knuckle'"));
  }
  const std::filesystem::path broken =
      write_text(scratch_dir("in2") / "broken.xml", "<polarform>\n<vessel radius=\"500\"\n");
  try {
    design_to(broken, dir);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), StartsWith(broken.string() + ":"));
  }
  EXPECT_TRUE(files_in(dir).empty());
}

TEST(VesselOutputs, InfeasibleDesignWritesNothing) {
  const std::filesystem::path dir = scratch_dir("out");
  const std::filesystem::path design =
      write_text(scratch_dir("in") / "contradictory.xml", contradictory_project());
  EXPECT_THROW(design_to(design, dir), InputError);
  EXPECT_TRUE(files_in(dir).empty());
}

}  // namespace
}  // namespace polarform
