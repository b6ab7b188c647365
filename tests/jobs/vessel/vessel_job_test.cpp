// The vessel job on the bundled examples and on bad designs: the measured conversion error meets
// the tolerance (also under an override), a hemisphere stays on its sphere through conversion and
// revolution with the membrane stresses pR/2t of a sphere, and infeasible designs are InputErrors.
#include "jobs/vessel/vessel_job.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/error.h"
#include "tests/support/jobs/vessel_job_support.h"

namespace polarform {
namespace {

using ::testing::HasSubstr;
using namespace vessel_job_test;

std::string error_of(const VesselProject& p) {
  try {
    run_vessel_job(p);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "no error";
}

TEST(VesselJob, EveryExampleMeetsItsTolerance) {
  for (const std::string& name : example_names()) {
    const VesselProject project = load_example(name);
    const VesselJobResult r = run_vessel_job(project);
    EXPECT_LE(r.converted.max_radial_error, project.tolerance) << name;
    EXPECT_GT(r.converted.max_radial_error, 0.0) << name;  // measured, not assumed
    EXPECT_NEAR(r.converted.surfaces.junction_radius, 500.0, 1e-9) << name;
    EXPECT_GT(r.seconds.total, 0.0) << name;
    if (r.solved.solution.exact) {  // the standard head: degree 2, on its closed form
      EXPECT_EQ(r.converted.profile.degree(), 2) << name;
      EXPECT_LT(r.converted.max_radial_error, 1e-9) << name;
      continue;
    }
    EXPECT_EQ(r.converted.conversion->tolerance, project.tolerance) << name;
    EXPECT_EQ(r.converted.conversion->max_radial_error, r.converted.max_radial_error) << name;
    // The product C = F·B (R's degree + 4, quartic quasi-uniform arcs, DESIGN §4.1), refitted
    // with fewer control points: each half of the meridian (junction to apex, apex to junction)
    // with R's end points and end tangents.
    const PolarConversion& c = *r.converted.conversion;
    const int synthesis_degree = r.solved.solution.minimum_stress
                                     ? r.solved.solution.minimum_stress->settings.degree
                                     : project.design.synthesis.degree;
    EXPECT_EQ(c.function.degree(), synthesis_degree) << name;
    ASSERT_EQ(c.steps.size(), 2u) << name;
    EXPECT_EQ(c.steps[1].name, "refit") << name;
    EXPECT_LT(c.curve.size(), c.steps[0].control_points) << name;
    EXPECT_GE(c.curve.degree(), 3) << name;
    EXPECT_LE(c.curve.degree(), 6) << name;
    if (const auto& m = r.solved.solution.minimum_stress) {
      EXPECT_GT(m->head.iterations, 0) << name;
      continue;
    }
    EXPECT_GT(r.solved.solution.synthesis.iterations, 0) << name;
    EXPECT_LE(r.solved.solution.synthesis.max_violation, 1e-6) << name;
  }
}

// The refitted meridian meets the shell tangentially (vertical at junction A, where R' = 0) and
// crosses the axis at θ = π/2 exactly, level there (R'(π/2) = 0 on every example head), so that
// the revolved head is G1 at its apex and with the cylinder.
TEST(VesselJob, RefittedMeridianIsTangentToTheShellAndLevelAtTheApex) {
  for (const std::string& name : example_names()) {
    const VesselJobResult r = run_vessel_job(load_example(name));
    if (r.solved.solution.exact) continue;
    const NurbsCurve2d& c = r.converted.profile;
    const auto at_start = c.derivatives(c.front(), 1);
    EXPECT_LE(std::abs(at_start[1].x()), 1e-12 * at_start[1].norm()) << name;
    EXPECT_NEAR(r.converted.surfaces.apex_parameter, std::numbers::pi / 2, 1e-12) << name;
    for (double side : {-1.0, 1.0}) {  // one-sided tangents at the apex knot
      const auto apex = c.derivatives(std::numbers::pi / 2 + side * 1e-13, 1);
      EXPECT_LE(std::abs(apex[1].y()), 1e-9 * apex[1].norm()) << name;
    }
    EXPECT_LE(std::abs(c(std::numbers::pi / 2).x()), 1e-9) << name;
  }
}

TEST(VesselJob, ToleranceOverrideIsMet) {
  VesselProject project = load_example("custom_curvature.xml");
  int previous_arcs = 0;
  for (double tolerance : {1e-2, 1e-4, 1e-6}) {
    project.tolerance = tolerance;
    const VesselJobResult r = run_vessel_job(project);
    EXPECT_LE(r.converted.conversion->max_radial_error, tolerance) << tolerance;
    EXPECT_GE(static_cast<int>(r.converted.conversion->arcs.size()), previous_arcs) << tolerance;
    previous_arcs = static_cast<int>(r.converted.conversion->arcs.size());
  }
}

// The hemisphere's curvature 1/R everywhere with the default end conditions is the sphere: the
// synthesis returns R = 500 (to 1e-10 in the synthesis tests), the converter's product makes it
// exactly and its refit within the tolerance.
TEST(VesselJob, HemisphereStaysOnItsSphere) {
  const VesselJobResult r = run_vessel_job(load_example("hemispherical.xml"));
  const double R = 500.0;
  EXPECT_LE(r.converted.conversion->max_radial_error, 1e-3);
  EXPECT_NEAR(r.solved.solution.depth, R, 1e-7);
  const NurbsCurve2d& c = r.converted.conversion->curve;
  double worst = 0.0;
  for (int k = 0; k <= 4000; ++k)
    worst = std::max(worst, std::abs(c(c.front() + (c.back() - c.front()) * k / 4000).norm() - R));
  EXPECT_LE(worst, 1e-3);
  EXPECT_LT(r.converted.conversion->steps[0].max_radial_error, 1e-7);  // the product: exact
  const NurbsSurface& head = r.converted.surfaces.head;
  double worst_surface = 0.0, lowest = 0.0;
  for (int i = 0; i <= 36; ++i)
    for (int j = 0; j <= 90; ++j) {
      const Eigen::Vector3d p =
          head(i / 36.0, head.front_v() + (head.back_v() - head.front_v()) * j / 90);
      worst_surface = std::max(worst_surface, std::abs(p.norm() - R));
      lowest = std::min(lowest, p.z());
    }
  EXPECT_LE(worst_surface, 1e-3);
  EXPECT_GE(lowest, -1e-9);
  // The cylinder from z = 0 down to −length at radius R.
  const NurbsSurface& cylinder = r.converted.surfaces.cylinder;
  for (double u : {0.0, 0.3, 0.7})
    for (double v : {cylinder.front_v(), cylinder.back_v()}) {
      const Eigen::Vector3d p = cylinder(u, v);
      EXPECT_NEAR(std::hypot(p.x(), p.y()), R, 1e-9);
    }
  EXPECT_NEAR(cylinder(0.2, cylinder.front_v()).z(), -1500.0, 1e-9);
}

// Membrane theory: a sphere carries pR/2t in both directions, the cylinder pR/t hoop and pR/2t
// axial (2 MPa, R = 500 mm, t = 10 mm: 50 and 100 MPa).
TEST(VesselJob, HemisphereMembraneStressIsPROver2T) {
  const VesselJobResult r = run_vessel_job(load_example("hemispherical.xml"));
  const double sphere = 2.0 * 500 / (2 * 10), cylinder = 2.0 * 500 / 10;
  int head_samples = 0;
  for (const StressSample& s : r.solved.solution.stresses.samples) {
    if (s.on_cylinder) {
      EXPECT_NEAR(s.hoop_stress, cylinder, 1e-12 * cylinder);
      EXPECT_NEAR(s.meridional_stress, sphere, 1e-12 * sphere);
      continue;
    }
    ++head_samples;
    EXPECT_NEAR(s.meridional_stress, sphere, 1e-9 * sphere) << s.theta;
    EXPECT_NEAR(s.hoop_stress, sphere, 1e-9 * sphere) << s.theta;
  }
  EXPECT_EQ(head_samples, 181);
  EXPECT_TRUE(r.solved.solution.stresses.compressive_hoop.empty());
}

// The 2:1 ellipsoidal example reproduces the ellipse (about 0.1 mm) and with it the known
// compressive hoop band at the equator, N_θ = −pR there (σ = −pR/t = −100 MPa).
TEST(VesselJob, EllipsoidalHeadHasTheCompressiveHoopBand) {
  const VesselJobResult r = run_vessel_job(load_example("ellipsoidal_2_1.xml"));
  ASSERT_TRUE(r.solved.solution.preset.has_value());
  EXPECT_LE(r.solved.solution.preset->max_deviation, 0.2);
  ASSERT_EQ(r.solved.solution.stresses.compressive_hoop.size(), 1u);
  const CompressiveBand& band = r.solved.solution.stresses.compressive_hoop.front();
  EXPECT_EQ(band.theta_from, 0.0);
  EXPECT_NEAR(band.min_hoop_stress, -100.0, 1.0);
  // The band ends where r2 = 2 r1 (N_θ = 0), within 0.01 rad of where the exact ellipse's does.
  ASSERT_EQ(r.solved.solution.preset->stresses.compressive_hoop.size(), 1u);
  EXPECT_NEAR(band.theta_to, r.solved.solution.preset->stresses.compressive_hoop.front().theta_to,
              0.01);
}

TEST(VesselJob, InfeasibleDesignsAreInputErrors) {
  std::vector<std::string> warnings;
  const VesselProject contradictory =
      parse_vessel_project(contradictory_project(), "c.xml", warnings);
  EXPECT_THAT(error_of(contradictory), HasSubstr("contradictory end conditions: R(π) = 480 mm"));
  EXPECT_THROW(run_vessel_job(contradictory), InputError);

  const VesselProject too_few = parse_vessel_project(
      vessel_xml("<head preset=\"hemispherical\"/>", "<synthesis degree=\"5\" ordinates=\"6\"/>"),
      "f.xml", warnings);
  EXPECT_THAT(error_of(too_few), HasSubstr("too few degrees of freedom"));
  EXPECT_THROW(run_vessel_job(too_few), InputError);

  VesselProject bad_tolerance = load_example("hemispherical.xml");
  bad_tolerance.tolerance = 0.0;
  EXPECT_THROW(run_vessel_job(bad_tolerance), InputError);
}

TEST(VesselJob, NonConvergenceIsANumericalErrorWithTheNumbers) {
  std::vector<std::string> warnings;
  const VesselProject p = parse_vessel_project(non_converging_project(), "n.xml", warnings);
  EXPECT_THAT(error_of(p), HasSubstr("did not converge within 2 evaluations (objective "));
  EXPECT_THROW(run_vessel_job(p), NumericalError);
}

}  // namespace
}  // namespace polarform
