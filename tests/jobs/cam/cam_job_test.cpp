// The cam job in memory: for every example the exported curve meets the tolerance under an
// independent dense sampling (and the job's measured error is the true maximum), the degree is the
// product degree, the curve is closed; the roller and flat-faced analyses equal textbook closed
// forms; tolerances below kMinTolerance are refused as bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "jobs/cam/cam_outputs.h"
#include "jobs/cam/cam_plots.h"
#include "jobs/cam/cam_report.h"
#include "src/error.h"
#include "src/number_text.h"
#include "tests/support/jobs/cam_job_support.h"
#include "tests/support/jobs/closed_forms.h"

namespace polarform {
namespace {

using namespace cam_job_test;

// ψ moved into [start, start + 2π).
double into_domain(double psi, double start) {
  while (psi < start) psi += 2 * kPi;
  while (psi >= start + 2 * kPi) psi -= 2 * kPi;
  return psi;
}

// Max |radius − R(ψ)| of a plate profile, or max |z − height(φ)| of a cylindrical track (whose
// points must also lie on the pitch cylinder), at `count` equally spaced curve parameters.
double sampled_error(const CamJobResult& r, int count) {
  const PolarFunction& R = r.conversion.profile_function;
  double worst = 0;
  for (int k = 0; k <= count; ++k) {
    if (r.plate()) {
      const NurbsCurve2d& c = plate_profile(r).curve;
      const double u = c.front() + (c.back() - c.front()) * k / count;
      const Eigen::Vector2d p = c(u);
      const double psi = into_domain(std::atan2(p.y(), p.x()), R.start);
      worst = std::max(worst, std::abs(p.norm() - R(psi)));
    } else {
      const NurbsCurve3d& c = track_of(r).curve;
      const double u = c.front() + (c.back() - c.front()) * k / count;
      const Eigen::Vector3d p = c(u);
      EXPECT_NEAR(p.head<2>().norm(), r.project().cam.cylinder_radius, 1e-9) << "u = " << u;
      const double phi = into_domain(std::atan2(p.y(), p.x()), R.start);
      worst = std::max(worst, std::abs(p.z() + track_of(r).offset - R(phi)));
    }
  }
  return worst;
}

TEST(CamJob, EveryExampleMeetsItsToleranceUnderIndependentSampling) {
  for (const std::string& name : kExampleNames) {
    const CamJobResult& r = example(name).result;
    const PolarConversion& c = r.conversion.conversion;
    const double measured = sampled_error(r, 40000);
    EXPECT_LE(measured, r.project().conversion.tolerance) << name;
    // The job's own figure is the maximum: dense sampling finds no more, and nearly as much.
    EXPECT_LE(measured, c.max_radial_error * (1 + 1e-9) + 1e-13) << name;
    EXPECT_GE(measured, 0.9 * c.max_radial_error) << name;
    EXPECT_LE(c.max_radial_error, c.tolerance) << name;
    EXPECT_LE(c.max_normal_error, c.max_radial_error + 1e-13) << name;
  }
}

TEST(CamJob, ProfileIsTheCompactedProductAndIsClosed) {
  for (const std::string& name : kExampleNames) {
    const CamJobResult& r = example(name).result;
    const int degree =
        r.conversion.conversion.function.spline().degree() + 4;  // quartic base: deg F + 4
    if (r.plate()) {
      // The product C = F·B, refitted with fewer control points (compaction="refit").
      const PolarConversion& conversion = r.conversion.conversion;
      const NurbsCurve2d& c = plate_profile(r).curve;
      ASSERT_EQ(conversion.steps.size(), 2u) << name;
      EXPECT_EQ(conversion.steps[0].name, "product") << name;
      EXPECT_EQ(conversion.steps[1].name, "refit") << name;
      EXPECT_EQ(conversion.steps[1].control_points, c.size()) << name;
      EXPECT_LT(c.size(), conversion.steps[0].control_points) << name;
      EXPECT_GE(c.degree(), 3) << name;
      EXPECT_LE(c.degree(), 6) << name;
      EXPECT_LT((c(c.front()) - c(c.back())).norm(), 1e-12) << name;
      ASSERT_TRUE(plate_profile(r).limited) << name;
      EXPECT_EQ(plate_profile(r).limited->curve.degree(), 3) << name;
      EXPECT_LE(plate_profile(r).limited->max_radial_error, r.project().conversion.tolerance)
          << name;
    } else {
      const NurbsCurve3d& c = track_of(r).curve;
      EXPECT_EQ(c.degree(), degree) << name;
      EXPECT_LT((c(c.front()) - c(c.back())).norm(), 1e-12) << name;
    }
  }
}

TEST(CamJob, RollerAnalysesEqualTheClosedForms) {
  const CamJobResult& r = example("roller").result;
  ASSERT_TRUE(std::holds_alternative<PlateCamAnalysis>(r.analysis.cam));
  const double prime = 50;  // base radius 40 + roller radius 10
  double pressure = 0, pitch_radius = INFINITY;
  for (int k = 0; k < 360000; ++k) {
    const double theta = k * 1e-3;
    const Motion m = roller_motion(theta);
    // Radial translating roller: tan α = s' / (Rb + Rr + s).
    pressure = std::max(pressure, std::abs(std::atan(m.v / (prime + m.s))));
    const double rho = polar_radius_of_curvature(prime + m.s, m.v, m.a);
    if (rho > 0) pitch_radius = std::min(pitch_radius, rho);
  }
  EXPECT_NEAR(plate_analysis(r).max_pressure_angle.value, pressure, 1e-9);
  EXPECT_NEAR(plate_analysis(r).min_convex_pitch_radius.value, pitch_radius, 1e-7);
  // The contour is the pitch curve offset inwards by the roller radius.
  EXPECT_NEAR(plate_analysis(r).min_convex_contour_radius.value, pitch_radius - 10, 1e-7);
  EXPECT_TRUE(plate_analysis(r).undercut.empty());
}

// The pitch curve's largest signed curvature on each side over 10^6 cam angles (+: convex).
std::pair<double, double> sampled_pitch_curvatures(const PlateCam& cam) {
  double convex = 0, concave = 0;
  for (int k = 0; k < 1000000; ++k) {
    const double kappa = cam.sample(2 * std::numbers::pi * k / 1000000).pitch_curvature;
    convex = std::max(convex, kappa);
    concave = std::max(concave, -kappa);
  }
  return {convex, concave};
}

TEST(CamJob, RollerPipeBoundEqualsTheConvexPitchRadius) {
  // MIT 13.472J M7-5: the roller is a pipe around the pitch curve; where the pitch curve is
  // convex at its tightest bend, the pipe code's 1/κ_max of the pitch curve's NURBS is the
  // analysis' min_convex_pitch_radius.
  const CamJobResult& r = example("roller").result;
  const auto& p = std::get<PlateCamAnalysis>(r.analysis.cam);
  ASSERT_TRUE(p.pipe_bound);
  const double convex = plate_analysis(r).min_convex_pitch_radius.value;
  RecordProperty("r_local", format_round_trip(p.pipe_bound->r_local));
  RecordProperty("min_convex_pitch_radius", format_round_trip(convex));
  EXPECT_NEAR(p.pipe_bound->r_local / convex, 1.0, 1e-6);
  EXPECT_DOUBLE_EQ(p.pipe_bound->kappa_max * p.pipe_bound->r_local, 1.0);
  const auto [most_convex, most_concave] =
      sampled_pitch_curvatures(std::get<PlateCam>(r.design.cam));
  EXPECT_GT(most_convex, most_concave);  // convex at its tightest bend, so the two agree
  const nlohmann::ordered_json j = cam_report_json(r, {});
  EXPECT_EQ(j["pipe_bound"]["r_local_mm"].get<double>(), p.pipe_bound->r_local);
  EXPECT_EQ(j["pipe_bound"]["kappa_max_per_mm"].get<double>(), p.pipe_bound->kappa_max);
  // Not a roller: no pipe bound.
  EXPECT_FALSE(std::get<PlateCamAnalysis>(example("flat_faced").result.analysis.cam).pipe_bound);
}

TEST(CamJob, APitchCurveConcaveAtItsTightestBendBoundsThePipeBelowTheConvexRadius) {
  // A short steep start of the rise at a small base radius: the pitch curve bends tighter on its
  // concave side than anywhere on its convex side. The pipe bound counts |κ| (the concave bend),
  // min_convex_pitch_radius only the convex side (what a roller undercuts).
  std::vector<std::string> warnings;
  const CamProject project = parse_cam_project(R"(<polarform version="1">
  <cam type="plate" follower="roller" base-radius="20" roller-radius="5" rpm="100">
    <segment kind="dwell" to="90"/>
    <segment kind="rise" law="polynomial" lift="2.6" to="105"><start v="0" a="0"/><end v="20" a="0"/></segment>
    <segment kind="rise" law="polynomial" lift="20" to="220"><start v="20" a="0"/><end v="0" a="0"/></segment>
    <segment kind="dwell" to="260"/>
    <segment kind="return" law="cycloidal" lift="22.6" to="360"/>
  </cam>
</polarform>)",
                                               "concave.xml", warnings);
  const CamDesignStage design = design_cam(project);
  const CamAnalysisStage analysis = analyse_cam(design);
  const auto& p = std::get<PlateCamAnalysis>(analysis.cam);
  ASSERT_TRUE(p.pipe_bound);
  const auto [most_convex, most_concave] = sampled_pitch_curvatures(std::get<PlateCam>(design.cam));
  RecordProperty("most_convex", format_round_trip(most_convex));
  RecordProperty("most_concave", format_round_trip(most_concave));
  ASSERT_GT(most_concave, 1.5 * most_convex);
  // The pipe bound: 1/κ_max with κ_max the concave bend (measured: within 1.3e-7 of the
  // samples' maximum, which 144 000 interpolation nodes put 9e-8 below the true one).
  EXPECT_NEAR(p.pipe_bound->kappa_max / most_concave, 1.0, 1e-6);
  // The cam's: the convex side only.
  EXPECT_NEAR(p.analysis.min_convex_pitch_radius.value * most_convex, 1.0, 1e-6);
}

TEST(CamJob, FlatFacedAnalysesEqualTheClosedForms) {
  const CamJobResult& r = example("flat_faced").result;
  ASSERT_TRUE(std::holds_alternative<PlateCamAnalysis>(r.analysis.cam));
  double radius = INFINITY;
  for (int k = 0; k < 360000; ++k) {
    double d[3];
    r.design.program.derivatives(k * 1e-3 * kRadiansPerDegree, 2, d);
    radius = std::min(radius, 35 + d[0] + d[2]);  // flat face: ρ = Rb + s + s''
  }
  EXPECT_NEAR(plate_analysis(r).min_convex_contour_radius.value, radius, 1e-7);
  EXPECT_EQ(plate_analysis(r).max_pressure_angle.value,
            0.0);  // a radial flat face pushes along its axis
  EXPECT_TRUE(plate_analysis(r).undercut.empty());
}

TEST(CamJob, RefusesToleranceBelowTheFloor) {
  CamProject p = load_example("roller");
  p.conversion.tolerance = 1e-12;
  try {
    run_cam_job(p);
    FAIL() << "no error for a 1e-12 mm tolerance";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("1e-12"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("1e-09"), std::string::npos) << e.what();
  }
}

// A degree-1 extra (a polyline) cannot meet 1e-8 mm within 20 000 spans; the exact profile can,
// so the job warns and goes on. (The degree-3 extra, its knots placed by need, reaches 1e-8 mm.)
TEST(CamJob, UnreachableDegreeLimitedProfileIsAWarningNotAFailure) {
  EXPECT_TRUE(example("roller").result.conversion.warnings.empty());
  CamProject p = load_example("offset_roller");
  p.conversion.tolerance = 1e-8;
  CamJobOptions options;
  options.limited_degree = 1;
  const CamJobResult r = run_cam_job(p, options);
  EXPECT_FALSE(plate_profile(r).limited.has_value());
  ASSERT_EQ(r.conversion.warnings.size(), 1u);
  EXPECT_NE(r.conversion.warnings[0].find("degree-1 profile not written"), std::string::npos)
      << r.conversion.warnings[0];
  EXPECT_NE(r.conversion.warnings[0].find("1e-08 mm"), std::string::npos)
      << r.conversion.warnings[0];
  EXPECT_LE(r.conversion.conversion.max_radial_error, 1e-8);
}

// The pressure-angle limit: the project's, else 30° (none for a flat face); beyond it a warning in
// the analysis stage and report.json (which both front ends print), never a failure.
TEST(CamJob, PressureAngleBeyondTheLimitIsWarnedAbout) {
  const CamJobResult& roller = example("roller").result;
  const double worst = plate_analysis(roller).max_pressure_angle.value;
  EXPECT_NEAR(*roller.analysis.pressure_angle_limit, 30.0 * kRadiansPerDegree, 1e-15);
  EXPECT_EQ(roller.analysis.warnings.empty(), worst <= 30.0 * kRadiansPerDegree);
  EXPECT_FALSE(example("flat_faced").result.analysis.pressure_angle_limit.has_value());

  CamProject p = load_example("roller");
  p.pressure_angle_limit = worst - 0.5 * kRadiansPerDegree;
  const CamAnalysisStage below = analyse_cam(design_cam(p));
  ASSERT_EQ(below.warnings.size(), 1u);
  EXPECT_NE(below.warnings[0].find("max pressure angle " + degrees_text(worst) + " at θ = " +
                                   degrees_text(plate_analysis(roller).max_pressure_angle.theta) +
                                   " exceeds the limit " + degrees_text(*p.pressure_angle_limit)),
            std::string::npos)
      << below.warnings[0];
  const nlohmann::json j = cam_report_fields(design_cam(p), below, nullptr);
  EXPECT_EQ(j["pressure_angle_within_limit"], false);
  EXPECT_NEAR(j["pressure_angle_limit_deg"].get<double>(), worst * kDegreesPerRadian - 0.5, 1e-9);
  EXPECT_EQ(j["warnings"].size(), 1u);

  p.pressure_angle_limit = worst + 0.5 * kRadiansPerDegree;
  const CamAnalysisStage above = analyse_cam(design_cam(p));
  EXPECT_TRUE(above.warnings.empty());
  EXPECT_EQ(cam_report_fields(design_cam(p), above, nullptr)["pressure_angle_within_limit"], true);
}

// The stages the studio runs live — design, analyses, and the conversion with fewer error samples
// and without the degree-limited extra — give every field of report.json that they compute, bit
// for bit: the numbers the studio shows are the report's.
TEST(CamJob, LiveStagesGiveTheReportsFields) {
  for (const std::string& name : kExampleNames) {
    SCOPED_TRACE(name);
    const CamJobResult& r = example(name).result;
    const CamDesignStage design = design_cam(r.project());
    const CamAnalysisStage analysis = analyse_cam(design);
    CamJobOptions live;
    live.error_samples = 720;
    live.with_limited = false;
    const CamConversionStage conversion = convert_cam(design, live);
    nlohmann::ordered_json shown = cam_report_fields(design, analysis, &conversion);
    nlohmann::ordered_json written = cam_report_fields(r.design, r.analysis, &r.conversion);
    written.erase("degree_limited");
    EXPECT_EQ(shown, written);
    EXPECT_EQ(conversion.error.angle.size(), 721u);
    EXPECT_EQ(r.conversion.error.angle.size(), 4001u);
  }
}

// The result's alternatives follow the design: a plate cam has a contour analysis and a profile,
// a cylindrical cam a pitch-radius analysis and a track; the continuity goes up to jerk.
TEST(CamJob, StagesHoldTheAlternativeOfTheCam) {
  const CamJobResult& roller = example("roller").result;
  EXPECT_TRUE(std::holds_alternative<PlateCam>(roller.design.cam));
  EXPECT_TRUE(std::holds_alternative<PlateCamAnalysis>(roller.analysis.cam));
  EXPECT_TRUE(std::holds_alternative<PlateProfile>(roller.conversion.profile));
  const CamJobResult& cylindrical = example("cylindrical").result;
  EXPECT_TRUE(std::holds_alternative<BarrelCam>(cylindrical.design.cam));
  EXPECT_TRUE(std::holds_alternative<CylindricalCamAnalysis>(cylindrical.analysis.cam));
  EXPECT_TRUE(std::holds_alternative<CylindricalTrack>(cylindrical.conversion.profile));
  // roller.xml: the cycloidal rise starts and ends with a jerk step of 4π²h/β³ (h = 20 mm,
  // β = π/2) against the dwells; displacement, velocity and acceleration are continuous.
  ASSERT_EQ(roller.design.continuity.size(), 2u);
  for (const ContinuityIssue& issue : roller.design.continuity) {
    EXPECT_EQ(issue.derivative, 3);
    EXPECT_NEAR(std::abs(issue.jump()), 4 * kPi * kPi * 20 / std::pow(kPi / 2, 3), 1e-9);
  }
}

// The developed track of a cylindrical cam reads like its motion program: at x = Rc·θ it is at
// the height z0 + s(θ) the follower has at cam angle θ, over 0 ≤ x ≤ 2π·Rc, drawn at 1:1.
TEST(CamJob, DevelopedTrackFollowsTheDirectionOfRotationAtTrueAspect) {
  const CamJobResult& r = example("cylindrical").result;
  const Figure f = profile_figure(r.design, r.analysis, r.conversion);
  const Plot& plot = f.panels().front();
  EXPECT_TRUE(plot.equal_aspect);
  const Series& track = plot.series().front();
  const double rc = r.project().cam.cylinder_radius, z0 = r.project().cam.z0;
  EXPECT_NEAR(track.x.front(), 0.0, 1e-9);
  EXPECT_NEAR(track.x.back(), 2 * kPi * rc, 1e-9);
  ASSERT_TRUE(std::is_sorted(track.x.begin(), track.x.end()));
  for (double degrees : {20.0, 100.0, 150.0, 200.0, 260.0, 330.0}) {
    const double theta = degrees * kPi / 180;
    const auto at = std::lower_bound(track.x.begin(), track.x.end(), rc * theta);
    const std::size_t i = static_cast<std::size_t>(at - track.x.begin());
    const double t = (rc * theta - track.x[i - 1]) / (track.x[i] - track.x[i - 1]);
    const double z = track.y[i - 1] + t * (track.y[i] - track.y[i - 1]);
    double s[4];
    r.design.program.derivatives(theta, 0, s);
    EXPECT_NEAR(z, z0 + s[0], 0.05) << degrees << "°";  // 2000 samples, linear interpolation
  }
}

// A flat face's pressure angle is fixed by its geometry; its plots show instead where the cam
// touches the face, x = σ s' − e from the axis, with the width the face needs from the analysis.
TEST(CamJob, FlatFacedPlotsShowTheContactOnTheFaceInsteadOfThePressureAngle) {
  const CamJobResult& r = example("flat_faced").result;
  const FaceWidth width = plate_analysis(r).face_width.value();
  SvajFigureOptions with_pressure;
  with_pressure.pressure_panel = true;
  const Figure analysis = analysis_figure(r.design, r.analysis);
  const Figure svaj = svaj_figure(r.design, r.analysis, with_pressure);
  for (const Plot* plot : {&analysis.panels().front(), &svaj.panels().back()}) {
    EXPECT_EQ(plot->y_label, "contact on the face [mm]");
    const std::vector<double>& contact = plot->series().front().y;
    const auto [lo, hi] = std::minmax_element(contact.begin(), contact.end());
    EXPECT_NEAR(*lo, width.left, 1e-3);  // grid samples against the refined extremes
    EXPECT_NEAR(*hi, width.right, 1e-3);
    ASSERT_EQ(plot->horizontal_lines().size(), 2u);
    EXPECT_EQ(plot->horizontal_lines()[0].value, width.right);
    EXPECT_EQ(plot->horizontal_lines()[1].value, width.left);
  }
  // Followers with a pressure angle keep its panel.
  const CamJobResult& roller = example("roller").result;
  EXPECT_EQ(analysis_figure(roller.design, roller.analysis).panels().front().y_label,
            "pressure angle [deg]");
}

// <dynamics>: a harmonic rise of 20 mm over 90° with m = 0.5 kg, k = 5 N/mm, F₀ = 50 N jumps from
// the closed-form speed ω² = (k h + F₀)/(m·1e-3·h π²/(2β²)) = 7500 s⁻² (827 rpm): at 1200 rpm it
// does, is warned about, and the report, key figures and force.svg say so; the project keeps it.
TEST(CamJob, FollowerDynamicsFromTheProject) {
  std::vector<std::string> warnings;
  const CamProject project = parse_cam_project(
      "<polarform version=\"1\"><cam follower=\"roller\" base-radius=\"40\" roller-radius=\"10\" "
      "rpm=\"1200\"><segment kind=\"dwell\" to=\"90\"/><segment kind=\"rise\" law=\"harmonic\" "
      "lift=\"20\" to=\"180\"/><segment kind=\"dwell\" to=\"240\"/><segment kind=\"return\" "
      "law=\"cycloidal\" to=\"360\"/></cam><dynamics mass=\"0.5\" spring-rate=\"5\" preload=\"50\" "
      "contact-width=\"12\"/></polarform>",
      "dyn.xml", warnings);
  ASSERT_TRUE(project.load);
  EXPECT_TRUE(parse_cam_project(cam_project_xml(project), "saved.xml", warnings) == project);
  const CamJobResult r = run_cam_job(project);
  ASSERT_TRUE(r.analysis.dynamics);
  const nlohmann::ordered_json j = cam_report_json(r, {});
  const double jump_rpm = std::sqrt(7500.0) * 60 / (2 * kPi);
  EXPECT_NEAR(j["dynamics"]["jump_rpm"].get<double>(), jump_rpm, 1e-9 * jump_rpm);
  EXPECT_TRUE(j["dynamics"]["jumps"].get<bool>());
  EXPECT_NEAR(j["dynamics"]["min_contact_force_at_deg"].get<double>(), 180.0, 1e-9);
  // At θ = 180⁻: F = m·1e-3·s''·ω² + k h + F₀ with s'' = −h π²/(2β²) = −40 mm/rad².
  const double w = 1200 * 2 * kPi / 60;
  EXPECT_NEAR(j["dynamics"]["min_contact_force_n"].get<double>(),
              0.5e-3 * -40 * w * w + 5 * 20 + 50, 1e-9);
  bool warned = false;
  for (const std::string& x : r.analysis.warnings) warned |= x.find("the follower jumps") == 0;
  EXPECT_TRUE(warned);
  EXPECT_GT(j["dynamics"]["max_contact_stress_mpa"].get<double>(), 0.0);
  const std::map<std::string, std::string> files = render_cam_outputs(r);
  for (const char* svg : {"force.svg", "torque.svg", "stress.svg"}) EXPECT_EQ(files.count(svg), 1u);
  // Without <dynamics>, no dynamics and no force.svg.
  EXPECT_TRUE(cam_report_json(example("roller").result, {})["dynamics"].is_null());
}

// The motion curves are sampled segment by segment: both one-sided values of a jump appear at the
// boundary, and the curves cover the revolution in order.
TEST(CamJob, MotionCurvesShowJumpsAsJumps) {
  const MotionCurves& m = example("roller").result.analysis.curves;
  ASSERT_EQ(m.theta.front(), 0.0);
  EXPECT_NEAR(m.theta.back(), 2 * kPi, 1e-12);
  EXPECT_TRUE(std::is_sorted(m.theta.begin(), m.theta.end()));
  std::vector<double> at_rise_start;
  for (std::size_t i = 0; i < m.theta.size(); ++i)
    if (std::abs(m.theta[i] - kPi / 2) < 1e-12) at_rise_start.push_back(m.j[i]);
  ASSERT_EQ(at_rise_start.size(), 2u);
  EXPECT_EQ(at_rise_start[0], 0.0);  // the dwell's end
  EXPECT_NEAR(at_rise_start[1], 4 * kPi * kPi * 20 / std::pow(kPi / 2, 3), 1e-9);
}

// The measured error curve is the converter's measure along the profile: sorted by polar angle
// over one turn, never above the conversion's maximum, and reaching nearly all of it.
TEST(CamJob, ErrorCurveIsTheMeasuredErrorAlongTheProfile) {
  for (const std::string& name : kExampleNames) {
    SCOPED_TRACE(name);
    const CamConversionStage& c = example(name).result.conversion;
    EXPECT_TRUE(std::is_sorted(c.error.angle.begin(), c.error.angle.end()));
    EXPECT_GE(c.error.angle.front(), 0.0);
    EXPECT_LT(c.error.angle.back(), 2 * kPi);
    const double worst = *std::max_element(c.error.error.begin(), c.error.error.end());
    EXPECT_LE(worst, c.conversion.max_radial_error * (1 + 1e-9));
    EXPECT_GE(worst, 0.8 * c.conversion.max_radial_error);
  }
}

}  // namespace
}  // namespace polarform
