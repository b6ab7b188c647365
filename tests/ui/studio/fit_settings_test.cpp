// The fit workspace's settings and fit project files: every setting survives settings → project
// → XML → project → settings exactly (frame overrides, fairness, base arcs and every method, the
// polar profile included); through the project the settings become the fit job's options
// (method, net or tolerance, closure, poles, frame), as `polarform fit` takes them.
#include "ui/studio/fit_settings.h"

#include <gtest/gtest.h>

#include "jobs/fit/fit_job.h"

namespace polarform::studio {
namespace {

FitSettings round_trip(const FitSettings& s) {
  std::vector<std::string> warnings;
  const FitProject p =
      parse_fit_project(fit_project_xml(fit_project(s, "scan.ply")), "fit.xml", warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(p.scan, std::filesystem::path("scan.ply"));
  return fit_settings(p);
}

TEST(FitSettings, ProjectFieldsRoundTrip) {
  FitSettings s;
  s.method = 2;
  s.degree_u = 2, s.degree_v = 4;
  s.automatic_net = false;
  s.size_u = 9, s.size_v = 30;
  s.revolution = static_cast<int>(RevolutionMode::no);
  s.closure = static_cast<int>(Closure::closed);
  s.pole = static_cast<int>(PoleTreatment::cap);
  s.fairness = static_cast<int>(FairnessOptions::Mode::gcv);
  s.fairness_weight = 3e-5;
  s.quartic_base = true;
  EXPECT_EQ(round_trip(s), s);

  s.use_tolerance = true;
  s.tolerance = 0.037;
  s.measure = static_cast<int>(ToleranceMeasure::p95);
  s.size_u = s.size_v = 12;  // not stored with a tolerance: back to the defaults
  s.automatic_net = true;
  EXPECT_EQ(round_trip(s), s);
  EXPECT_EQ(round_trip(FitSettings{}), FitSettings{});
}

TEST(FitSettings, FrameOverridesSkipBadAndRejectOutliersRoundTrip) {
  FitSettings s;
  s.center = Eigen::Vector3d(1.5, -2, 3.25);
  s.axis = Eigen::Vector3d(0, 0.6, 0.8);
  s.skip_bad = false;
  EXPECT_EQ(round_trip(s), s);
  s.reject_outliers = true;
  EXPECT_EQ(round_trip(s), s);
  EXPECT_TRUE(fit_job_options(fit_project(s, "a.xyz")).reject_outliers);
}

TEST(FitSettings, EveryMethodRoundTrips) {
  for (FitJobMethod m : {FitJobMethod::automatic, FitJobMethod::polar, FitJobMethod::spherical,
                         FitJobMethod::cylindrical}) {
    FitSettings s;
    s.method = static_cast<int>(m);
    EXPECT_EQ(round_trip(s), s);
    EXPECT_EQ(fit_job_options(fit_project(s, "a.xyz")).method, m);
  }
}

TEST(FitSettings, BecomeTheFitJobsOptions) {
  FitSettings s;
  s.method = static_cast<int>(FitJobMethod::spherical);
  s.pole = static_cast<int>(PoleTreatment::g1);
  FitJobOptions o = fit_job_options(fit_project(s, "a.xyz"));
  EXPECT_FALSE(o.ctrl);  // by default the net is chosen by the data
  EXPECT_EQ(o.revolution, RevolutionMode::automatic);
  s.automatic_net = false;
  s.size_u = 10, s.size_v = 20;
  s.revolution = static_cast<int>(RevolutionMode::yes);
  o = fit_job_options(fit_project(s, "a.xyz"));
  EXPECT_EQ(o.revolution, RevolutionMode::yes);
  EXPECT_EQ(o.method, FitJobMethod::spherical);
  EXPECT_EQ(o.ctrl, std::make_pair(10, 20));
  EXPECT_FALSE(o.tolerance);  // a fixed net
  EXPECT_EQ(o.pole, PoleTreatment::g1);
  EXPECT_FALSE(o.center);  // estimated
  EXPECT_FALSE(o.axis);
  s.center = Eigen::Vector3d(4, 5, 6);
  s.axis = Eigen::Vector3d(1, 0, 0);
  o = fit_job_options(fit_project(s, "a.xyz"));
  EXPECT_EQ(o.center, s.center);
  EXPECT_EQ(o.axis, s.axis);
  s.use_tolerance = true;
  s.tolerance = 0.2;
  o = fit_job_options(fit_project(s, "a.xyz"));
  EXPECT_EQ(o.tolerance, 0.2);
  EXPECT_FALSE(o.ctrl);  // refined adaptively
}

}  // namespace
}  // namespace polarform::studio
