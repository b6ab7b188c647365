// A conical head through the vessel job: <head preset="conical" half-angle knuckle> read (degrees
// in the file, radians inside) and saved, the exact (2, 2) head on its cone and knuckle torus,
// the UG-32(h) check, the closed-form measures and the report's standard-head fields.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

#include "designers/vessel/head_measures.h"
#include "jobs/vessel/vessel_outputs.h"
#include "src/error.h"
#include "tests/support/export/exchange_fixtures.h"
#include "tests/support/jobs/vessel_job_support.h"

namespace polarform {
namespace {

using namespace vessel_job_test;
constexpr double kPi = std::numbers::pi;

TEST(ConicalHeadJob, ExampleIsTheExactToriconicalHead) {
  const VesselProject project = load_example("toriconical_30.xml");
  ASSERT_TRUE(project.design.preset);
  EXPECT_EQ(project.design.preset->kind, HeadKind::conical);
  EXPECT_NEAR(project.design.preset->half_angle, kPi / 6, 1e-15);
  EXPECT_EQ(project.design.preset->knuckle, 60.0);
  const VesselJobResult r = run_vessel_job(project);
  ASSERT_TRUE(r.solved.solution.exact);
  EXPECT_EQ(r.converted.profile.degree(), 2);
  EXPECT_EQ(r.converted.surfaces.head.degree_u(), 2);
  EXPECT_EQ(r.converted.surfaces.head.degree_v(), 2);
  // Independently of the job: every point of the revolved head on the knuckle torus or the cone.
  const double a = kPi / 6, kx = 440, tz = 60 * std::sin(a);
  const double apex = tz + (kx + 60 * std::cos(a)) / std::tan(a);
  EXPECT_NEAR(r.solved.solution.depth, apex, 1e-9);
  double worst = 0;
  const NurbsSurface& head = r.converted.surfaces.head;
  for (double u : exchange_test::linspace(head.front_u(), head.back_u(), 37))
    for (double v : exchange_test::linspace(head.front_v(), head.back_v(), 41)) {
      const Eigen::Vector3d p = head.point(u, v);
      const double rho = std::hypot(p.x(), p.y());
      const double off = p.z() < tz - 1e-9 ? std::hypot(rho - kx, p.z()) - 60
                                           : rho * std::cos(a) + (p.z() - apex) * std::sin(a);
      worst = std::max(worst, std::abs(off));
    }
  EXPECT_LT(worst, 1e-9);
  // UG-32(h) on the corroded dimensions, the measures of the closed form.
  ASSERT_TRUE(r.solved.solution.code && r.solved.solution.code->head);
  EXPECT_NE(r.solved.solution.code->head->thickness_formula.find("UG-32(h)"), std::string::npos);
  ASSERT_TRUE(r.solved.solution.measures);
  EXPECT_DOUBLE_EQ(r.solved.solution.measures->head_volume,
                   conical_head_measures(500, kPi / 6, 60).volume);
  const nlohmann::json j = vessel_report_json(r, {});
  EXPECT_EQ(j["head"]["standard"]["kind"], "conical");
  EXPECT_NEAR(j["head"]["standard"]["half_angle_deg"].get<double>(), 30.0, 1e-12);
  EXPECT_EQ(j["head"]["standard"]["knuckle_mm"], 60.0);
  // The cone point at the apex is said.
  bool cone_point = false;
  for (const std::string& w : r.solved.solution.warnings)
    cone_point |= w.find("cone point") != std::string::npos;
  EXPECT_TRUE(cone_point);
}

TEST(ConicalHeadJob, ProjectReadsBackAndRefusesBadAngles) {
  std::vector<std::string> warnings;
  const VesselProject p = parse_vessel_project(
      vessel_xml("<head preset=\"conical\" half-angle=\"45\"/>", ""), "cone.xml", warnings);
  EXPECT_EQ(p.design.preset->knuckle, 0.0);  // a plain cone
  EXPECT_EQ(parse_vessel_project(vessel_project_xml(p), "again.xml", warnings), p);
  const auto error = [](const std::string& head) {
    try {
      std::vector<std::string> w;
      parse_vessel_project(vessel_xml(head, ""), "bad.xml", w);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error("<head preset=\"conical\"/>").find("half-angle"), std::string::npos);
  EXPECT_NE(error("<head preset=\"conical\" half-angle=\"90\"/>").find("half-angle"),
            std::string::npos);
  EXPECT_NE(error("<head preset=\"conical\" half-angle=\"30\" knuckle=\"500\"/>").find("knuckle"),
            std::string::npos);
}

}  // namespace
}  // namespace polarform
