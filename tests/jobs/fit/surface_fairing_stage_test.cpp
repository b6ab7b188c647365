// `fit --fair` on a surface: a noisy vase fitted cylindrically has the rows and columns of its
// F(u, v) faired (Farin), its error measured again on the faired surface, and report.json's
// "fairing" states what was done; a spherical fit with a pole cap is refused by name.
#include "jobs/fit/surface_fairing_stage.h"

#include <gtest/gtest.h>

#include "jobs/fit/fit_job.h"
#include "jobs/fit/fit_outputs.h"
#include "src/error.h"
#include "tests/support/designers/synthetic_scans.h"

namespace polarform {
namespace {

TEST(SurfaceFairingStage, ANoisyVaseIsFairedAndReported) {
  FitJobOptions o;
  o.ctrl = std::pair{16, 16};
  const FitJobResult plain = run_fit_job(vase_cloud(8000, 0.02, 11), "vase", o);
  o.fairing = ProfileFairingOptions{FairingMethod::farin, 0.0, 100};
  const FitJobResult r = run_fit_job(vase_cloud(8000, 0.02, 11), "vase", o);
  EXPECT_EQ(r.method, "cylindrical");
  ASSERT_TRUE(r.surface_fairing);
  const SurfaceFitFairing& f = *r.surface_fairing;
  EXPECT_DOUBLE_EQ(f.tolerance, 3 * plain.report().error.rms);
  EXPECT_EQ(f.error_before, plain.report().error.max);
  EXPECT_GT(f.u.steps.size() + f.v.steps.size(), 0u);
  EXPECT_LE(f.measured_deviation, f.u.bound + f.v.bound);
  EXPECT_LE(f.u.bound + f.v.bound, f.tolerance);
  // The error is measured again on the faired surface: it stays at the noise.
  EXPECT_NE(r.report().error.rms, plain.report().error.rms);
  EXPECT_NEAR(r.report().error.rms, 0.02, 0.1 * 0.02);
  EXPECT_LE(r.report().error.max, f.error_before + f.measured_deviation);
  const nlohmann::ordered_json j = fit_report_fields(r);
  ASSERT_TRUE(j.contains("fairing"));
  EXPECT_EQ(j["fairing"]["method"], "farin");
  EXPECT_EQ(j["fairing"]["passes"].get<std::size_t>(), f.u.steps.size() + f.v.steps.size());
  EXPECT_EQ(j["fairing"]["knots_faired"].size(), f.u.steps.size() + f.v.steps.size());
  EXPECT_EQ(j["fairing"]["measured_deviation_mm"].get<double>(), f.measured_deviation);
  const auto content = render_fit_outputs(r);
  ASSERT_TRUE(content.count("fairing.svg"));
  EXPECT_FALSE(render_fit_outputs(plain).count("fairing.svg"));
  const Figure fig = surface_fairing_figure(f);
  ASSERT_EQ(fig.panels().size(), 2u);
  EXPECT_EQ(fig.panels()[0].series()[0].y.size(), f.u.steps.size());
  EXPECT_EQ(fig.panels()[1].series()[1].y.size(), f.v.steps.size());
}

TEST(SurfaceFairingStage, ASphericalFitWithAPoleCapIsRefusedByName) {
  FitJobOptions o;
  o.pole = PoleTreatment::cap;
  o.fairing = ProfileFairingOptions{};
  try {
    run_fit_job(sphere_cloud(2000, 25.0, Eigen::Vector3d(1, 2, 3), 7), "sphere", o);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("closes a pole with a cap"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace polarform
