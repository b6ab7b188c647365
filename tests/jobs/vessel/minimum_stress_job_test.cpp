// The minimum-stress head through the vessel job: the project's <head design="minimum-stress">
// rules (depth from the attribute or the preset, junction-kappa, what it refuses), the report's
// side-by-side comparison with the standard heads of the same depth, same_depth.svg, the saved
// project read back, and the head converted within the tolerance like every synthesised head.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <numbers>

#include "designers/vessel/polar_curvature.h"
#include "jobs/project/vessel_project.h"
#include "jobs/vessel/vessel_outputs.h"
#include "src/error.h"
#include "tests/support/jobs/vessel_job_support.h"

namespace polarform {
namespace {

using namespace vessel_job_test;

VesselProject parse(const std::string& xml) {
  std::vector<std::string> warnings;
  VesselProject p = parse_vessel_project(xml, "head.xml", warnings);
  EXPECT_TRUE(warnings.empty());
  return p;
}

std::string head_only(const std::string& head) { return vessel_xml(head, ""); }

TEST(MinimumStressJob, TheDepthComesFromTheAttributeOrThePreset) {
  const VesselProject from_preset =
      parse(head_only("<head design=\"minimum-stress\" preset=\"ellipsoidal\" ratio=\"2\"/>"));
  EXPECT_EQ(from_preset.design.head_design, HeadDesign::minimum_stress);
  EXPECT_FALSE(from_preset.design.depth);
  const VesselJobResult r = run_vessel_job(from_preset);
  ASSERT_TRUE(r.solved.solution.minimum_stress);
  EXPECT_NEAR(r.solved.solution.depth, 250.0, 1e-9);
  EXPECT_LE(r.converted.max_radial_error, from_preset.tolerance);
  ASSERT_TRUE(r.solved.solution.preset);  // the preset is compared

  const VesselProject given =
      parse(head_only("<head design=\"minimum-stress\" depth=\"200\" junction-kappa=\"0\"/>"));
  ASSERT_TRUE(given.design.depth);
  EXPECT_EQ(*given.design.depth, 200.0);
  const VesselSolveStage s = solve_vessel_head(given);
  EXPECT_NEAR(s.solution.depth, 200.0, 1e-9);
  EXPECT_NEAR(s.solution.junction_curvature, 0.0, 1e-12);
  EXPECT_FALSE(s.solution.preset);
}

TEST(MinimumStressJob, ReportPutsTheStandardHeadsOfTheDepthBesideIt) {
  const VesselJobResult r = run_vessel_job(load_example("minimum_stress_2_1_depth.xml"));
  const nlohmann::json j = vessel_report_json(r, {});
  EXPECT_EQ(j["head"]["design"], "minimum-stress");
  EXPECT_TRUE(j["synthesis"].is_null());
  const nlohmann::json& m = j["minimum_stress"];
  ASSERT_EQ(m["same_depth"].size(), 3u);
  // The ellipse of the 2:1 depth peaks at p a / t = 1 · 500 / 10 MPa (apex and equator).
  EXPECT_NEAR(m["same_depth"][0]["peak_stress_mpa"].get<double>(), 50.0, 1e-9);
  const double peak = m["head"]["peak_stress_mpa"].get<double>();
  double best = 1e300;
  for (const auto& h : m["same_depth"]) best = std::min(best, h["peak_stress_mpa"].get<double>());
  EXPECT_LT(peak, 0.9 * best);
  EXPECT_NEAR(m["peak_below_best_standard_pct"].get<double>(), 100 * (1 - peak / best), 1e-9);
  // The report's peak is the stress profile's own largest |σ| over the head.
  double largest = 0;
  for (const StressSample& k : r.solved.solution.stresses.samples)
    if (!k.on_cylinder)
      largest = std::max({largest, std::abs(k.hoop_stress), std::abs(k.meridional_stress)});
  EXPECT_DOUBLE_EQ(peak, largest);
  const std::map<std::string, std::string> files = render_vessel_outputs(r, {});
  ASSERT_TRUE(files.count("same_depth.svg"));
  EXPECT_NE(files.at("report.html").find("Heads of the same depth"), std::string::npos);
}

TEST(MinimumStressJob, SavedProjectReadsBack) {
  VesselProject p =
      parse(head_only("<head design=\"minimum-stress\" depth=\"220\" junction-kappa=\"0.001\"/>"));
  std::vector<std::string> warnings;
  EXPECT_EQ(parse_vessel_project(vessel_project_xml(p), "saved.xml", warnings), p);
  p =
      parse(head_only("<head design=\"minimum-stress\" preset=\"torispherical\" crown=\"1000\" "
                      "knuckle=\"60\"/>"));
  EXPECT_EQ(parse_vessel_project(vessel_project_xml(p), "saved.xml", warnings), p);
}

TEST(MinimumStressJob, InchProjectsGiveMillimetres) {
  const VesselProject p = parse(
      "<?xml version=\"1.0\"?><polarform version=\"1\" units=\"inch\"><vessel radius=\"20\" "
      "length=\"60\" thickness=\"0.5\" pressure=\"1\"><head design=\"minimum-stress\" depth=\"10\" "
      "junction-kappa=\"0.01\"/></vessel></polarform>");
  EXPECT_DOUBLE_EQ(*p.design.depth, 254.0);
  EXPECT_DOUBLE_EQ(*p.design.junction_kappa, 0.01 / 25.4);
}

TEST(MinimumStressJob, BadHeadsNameTheAttribute) {
  const auto error = [](const std::string& head) {
    try {
      std::vector<std::string> warnings;
      parse_vessel_project(head_only(head), "bad.xml", warnings);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("<head design=\"minimum-stress\"/>").find("depth"), std::string::npos);
  EXPECT_NE(error("<head design=\"minimum-stress\" depth=\"-3\"/>").find("depth"),
            std::string::npos);
  EXPECT_NE(error("<head design=\"minimum-stress\" depth=\"2001\"/>").find("depth"),
            std::string::npos);
  EXPECT_NE(error("<head preset=\"hemispherical\" depth=\"200\"/>").find("depth"),
            std::string::npos);
  EXPECT_NE(error("<head design=\"minimum-stress\" depth=\"200\"/><curvature theta=\"30\" "
                  "kappa=\"0.002\"/>")
                .find("design"),
            std::string::npos);
}

}  // namespace
}  // namespace polarform
