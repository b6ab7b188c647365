// The cam job's CAD files carry the job's curves: profile.dxf / track.dxf, profile.igs / track.igs
// and profile_deg3.dxf, parsed back number by number, have the in-memory curve's degree, knots,
// weights and control points (the plate profile in the z = 0 plane), and the DXF also the base
// circle. A project max-degree makes the files carry the capped approximation instead.
#include <gtest/gtest.h>

#include "tests/jobs/cam/spline_readers.h"
#include "tests/support/jobs/cam_job_support.h"

namespace polarform {
namespace {

using namespace cam_job_test;

template <int Dim>
void expect_same_curve(const ReadSpline& read, const NurbsCurve<Dim>& c, bool weights_always) {
  EXPECT_EQ(read.degree, c.degree());
  EXPECT_EQ(read.knots, c.knots());
  if (weights_always || c.is_rational()) {
    EXPECT_EQ(read.weights, c.weights());
  } else {
    EXPECT_TRUE(read.weights.empty());
  }
  ASSERT_EQ(read.points.size(), static_cast<std::size_t>(c.size()));
  for (int i = 0; i < c.size(); ++i) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    p.head<Dim>() = c.control_point(i);
    EXPECT_EQ(read.points[i], p) << "control point " << i;
  }
}

TEST(CamExchange, DxfSplinesAreTheJobsCurves) {
  for (const std::string& name : kExampleNames) {
    const ExampleRun& run = example(name);
    const CamJobResult& r = run.result;
    SCOPED_TRACE(name);
    const std::string stem = r.plate() ? "profile" : "track";
    const std::string text = slurp(run.dir / (stem + ".dxf"));
    const std::vector<ReadSpline> splines = read_dxf_splines(text);
    ASSERT_EQ(splines.size(), 1u);
    EXPECT_EQ(splines[0].layer, r.plate() ? "PROFILE" : "TRACK");
    const bool rational = r.plate() ? plate_profile(r).curve.is_rational() : true;
    EXPECT_EQ(splines[0].flags & 4, rational ? 4 : 0);
    if (r.plate()) {
      expect_same_curve(splines[0], plate_profile(r).curve, false);
      // The base circle: a CIRCLE on layer BASE_CIRCLE with the design's base radius.
      const std::vector<ReadCircle> circles = read_dxf_circles(text);
      ASSERT_EQ(circles.size(), 1u);
      EXPECT_EQ(circles[0].layer, "BASE_CIRCLE");
      EXPECT_EQ(circles[0].radius, r.project().cam.base_radius);
      const std::string deg3 = slurp(run.dir / "profile_deg3.dxf");
      const std::vector<ReadSpline> limited = read_dxf_splines(deg3);
      ASSERT_EQ(limited.size(), 1u);
      expect_same_curve(limited[0], plate_profile(r).limited->curve, false);
      // The degree-3 drawing carries the same base circle.
      const std::vector<ReadCircle> deg3_circles = read_dxf_circles(deg3);
      ASSERT_EQ(deg3_circles.size(), 1u);
      EXPECT_EQ(deg3_circles[0].layer, "BASE_CIRCLE");
      EXPECT_EQ(deg3_circles[0].radius, r.project().cam.base_radius);
    } else {
      expect_same_curve(splines[0], track_of(r).curve, false);
    }
  }
}

TEST(CamExchange, IgesCurvesAreTheJobsCurves) {
  for (const std::string& name : kExampleNames) {
    const ExampleRun& run = example(name);
    const CamJobResult& r = run.result;
    SCOPED_TRACE(name);
    const std::vector<ReadSpline> curves =
        read_iges_curves(slurp(run.dir / (r.plate() ? "profile.igs" : "track.igs")));
    ASSERT_EQ(curves.size(), 1u);
    if (r.plate()) {
      expect_same_curve(curves[0], plate_profile(r).curve, true);
    } else {
      expect_same_curve(curves[0], track_of(r).curve, true);
    }
  }
}

TEST(CamExchange, MaxDegreeExportsTheCappedProfile) {
  CamProject p = load_example("roller");
  p.conversion.compaction = Compaction::none;  // the product C = F·B, degree 9
  p.max_degree = 5;
  const CamJobResult r = run_cam_job(p);
  ASSERT_TRUE(plate_profile(r).capped);
  EXPECT_EQ(plate_profile(r).curve.degree(), 9);  // the exact profile is kept in memory
  EXPECT_EQ(plate_profile(r).capped->curve.degree(), 5);
  EXPECT_LE(plate_profile(r).capped->max_radial_error, p.conversion.tolerance);
  const ScratchDir dir("max_degree");
  write_cam_outputs(r, dir.path());
  const std::vector<ReadSpline> iges = read_iges_curves(slurp(dir / "profile.igs"));
  ASSERT_EQ(iges.size(), 1u);
  expect_same_curve(iges[0], plate_profile(r).capped->curve, true);
  const std::vector<ReadSpline> dxf = read_dxf_splines(slurp(dir / "profile.dxf"));
  ASSERT_EQ(dxf.size(), 1u);
  expect_same_curve(dxf[0], plate_profile(r).capped->curve, false);
  const json report = read_json(dir / "report.json");
  EXPECT_EQ(report["exported_profile"]["degree"], 5);
  EXPECT_EQ(report["exported_profile"]["control_points"].get<int>(),
            plate_profile(r).capped->curve.size());
  EXPECT_LE(report["exported_profile"]["max_radial_error_mm"].get<double>(), 1e-3);
  EXPECT_EQ(report["degree"], 9);  // the report's main fields describe the exact profile
}

}  // namespace
}  // namespace polarform
