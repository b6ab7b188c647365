// The fit workspace's settings and fit project files: every setting survives settings → project
// → XML → project → settings exactly (frame overrides, fairness and base arcs included); the
// polar method, which the studio does not fit, is named; the settings become the fitter's options
// (method, net or tolerance, closure, poles, frame).
#include <gtest/gtest.h>

#include "ui/studio/fit_settings.h"

namespace polarform::studio {
namespace {

FitSettings round_trip(const FitSettings& s) {
  std::vector<std::string> warnings, ignored;
  const FitProject p =
      parse_fit_project(fit_project_xml(fit_project(s, "scan.ply")), "fit.xml", warnings);
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(p.scan, std::filesystem::path("scan.ply"));
  const FitSettings back = fit_settings(p, ignored);
  EXPECT_TRUE(ignored.empty());
  return back;
}

TEST(FitSettings, ProjectFieldsRoundTrip) {
  FitSettings s;
  s.method = 2;
  s.degree_u = 2, s.degree_v = 4;
  s.size_u = 9, s.size_v = 30;
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
  EXPECT_EQ(round_trip(s), s);
  EXPECT_EQ(round_trip(FitSettings{}), FitSettings{});
}

TEST(FitSettings, FrameOverridesAndSkipBadRoundTrip) {
  FitSettings s;
  s.center = Eigen::Vector3d(1.5, -2, 3.25);
  s.axis = Eigen::Vector3d(0, 0.6, 0.8);
  s.skip_bad = false;
  EXPECT_EQ(round_trip(s), s);
}

TEST(FitSettings, ThePolarMethodIsNamedAsNotUsed) {
  FitProject p;
  p.scan = "a.xyz";
  p.method = FitJobMethod::polar;
  p.center = Eigen::Vector3d(1, 2, 3);
  p.axis = Eigen::Vector3d(0, 0, 1);
  std::vector<std::string> ignored;
  const FitSettings s = fit_settings(p, ignored);
  EXPECT_EQ(s.method, 0);
  ASSERT_EQ(ignored.size(), 1u);
  EXPECT_NE(ignored[0].find("polar"), std::string::npos);
  EXPECT_EQ(s.center, p.center);
  EXPECT_EQ(s.axis, p.axis);
}

TEST(FitSettings, BecomeTheFittersOptions) {
  FitSettings s;
  s.method = 1;
  s.size_u = 10, s.size_v = 20;
  s.pole = static_cast<int>(PoleTreatment::g1);
  RotationalFitOptions o = to_fit_options(s, 3);
  EXPECT_EQ(o.method, FitMethod::spherical);
  EXPECT_EQ(o.spherical.function.size_u, 10);
  EXPECT_EQ(o.spherical.function.size_v, 20);
  EXPECT_EQ(o.spherical.function.tolerance, 0.0);  // a fixed net
  EXPECT_EQ(o.spherical.north, PoleTreatment::g1);
  EXPECT_EQ(o.spherical.south, PoleTreatment::g1);
  EXPECT_EQ(o.spherical.function.threads, 3);
  EXPECT_FALSE(o.spherical.frame.origin);  // estimated
  EXPECT_FALSE(o.cylindrical.frame.axis);
  s.center = Eigen::Vector3d(4, 5, 6);
  s.axis = Eigen::Vector3d(1, 0, 0);
  o = to_fit_options(s, 3);
  EXPECT_EQ(o.spherical.frame.origin, s.center);
  EXPECT_EQ(o.cylindrical.frame.origin, s.center);
  EXPECT_EQ(o.spherical.frame.axis, s.axis);
  EXPECT_EQ(o.cylindrical.frame.axis, s.axis);
  s.use_tolerance = true;
  s.tolerance = 0.2;
  o = to_fit_options(s, 1);
  EXPECT_EQ(o.cylindrical.function.tolerance, 0.2);
  EXPECT_EQ(o.cylindrical.function.size_u, 0);  // refined adaptively
}

}  // namespace
}  // namespace polarform::studio
