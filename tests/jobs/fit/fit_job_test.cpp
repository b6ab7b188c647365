// The fit job on synthetic scans with known answers: the method chosen, the exact degrees of true
// circles, spheres, cylinders and surfaces of revolution with round-off errors, a noisy
// rotational freeform shape fitted to the noise level; a profile with its bore named as two loops,
// outliers refused or rejected, an extrapolated pole warned about.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>

#include "jobs/fit/fit_job.h"
#include "src/error.h"
#include "tests/support/designers/synthetic_scans.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(FitJob, ExactSphereGivesDegreeTwoTwoAtRoundOff) {
  const Eigen::Vector3d centre(3, -4, 12);
  const FitJobResult r = run_fit_job(sphere_cloud(2000, 25.0, centre, 7), "sphere");
  EXPECT_EQ(r.method, "spherical");
  const FitReport& rep = r.report();
  EXPECT_EQ(rep.nurbs_degree_u, 2);
  EXPECT_EQ(rep.nurbs_degree_v, 2);
  EXPECT_LT(rep.error.max, 1e-9);
  EXPECT_LT((std::get<RotationalFit>(r.fit).frame().frame.origin - centre).norm(), 1e-9);
  RecordProperty("max_error_mm", std::to_string(rep.error.max));
}

TEST(FitJob, ExactCylinderGivesDegreeOneTwo) {
  const FitJobResult r = run_fit_job(cone_cloud(2000, 18.0, 0.0, 50.0, 8), "cylinder");
  EXPECT_EQ(r.method, "cylindrical");
  EXPECT_EQ(r.report().nurbs_degree_u, 1);
  EXPECT_EQ(r.report().nurbs_degree_v, 2);
  EXPECT_LT(r.report().error.max, 1e-9);
}

TEST(FitJob, ConeAsSurfaceOfRevolutionGivesDegreeThreeTwo) {
  FitJobOptions o;
  o.method = FitJobMethod::cylindrical;
  const FitJobResult r = run_fit_job(cone_cloud(2000, 10.0, 0.25, 40.0, 9), "cone", o);
  EXPECT_EQ(r.report().nurbs_degree_u, 3);
  EXPECT_EQ(r.report().nurbs_degree_v, 2);
  EXPECT_LT(r.report().error.max, 1e-9);
}

TEST(FitJob, PlanarCircleIsAPolarCurveOfDegreeTwo) {
  Eigen::Matrix3Xd p(3, 400);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> T(0, 2 * kPi);
  for (Eigen::Index k = 0; k < p.cols(); ++k) {
    const double t = T(rng);
    p.col(k) = Eigen::Vector3d(5 + 20 * std::cos(t), -2 + 20 * std::sin(t), 7.5);
  }
  const FitJobResult r = run_fit_job(p, "circle");
  EXPECT_EQ(r.method, "polar");
  ASSERT_TRUE(r.profile());
  const NurbsCurve3d& curve = std::get<ProfileFit>(r.fit).curve;
  EXPECT_EQ(curve.degree(), 2);
  EXPECT_LT(r.report().error.max, 1e-9);
  EXPECT_NEAR(curve.point(curve.front()).z(), 7.5, 1e-12);
}

TEST(FitJob, NoisyVaseIsFittedToTheNoiseLevel) {
  const double sigma = 0.02;
  FitJobOptions o;
  o.ctrl = std::pair{16, 16};
  const FitJobResult r = run_fit_job(vase_cloud(8000, sigma, 11), "vase", o);
  EXPECT_EQ(r.method, "cylindrical");
  const double rms = r.report().error.rms;
  EXPECT_NEAR(rms, sigma, 0.1 * sigma);
  RecordProperty("rms_over_sigma", std::to_string(rms / sigma));
}

TEST(FitJob, BundledSphereLikeScanIsFittedToItsStatedNoise) {
  // examples/scans/sphere_like.xyz states N(0, 0.02²) mm per coordinate; three lobes in θ need
  // 24 control values around.
  FitJobOptions o;
  o.ctrl = std::pair{12, 24};
  const FitJobResult r =
      run_fit_job(std::filesystem::path(POLARFORM_SOURCE_DIR) / "examples/scans/sphere_like.xyz", o);
  EXPECT_EQ(r.method, "spherical");
  EXPECT_NEAR(r.report().error.rms, 0.02, 0.002);
  RecordProperty("rms_mm", std::to_string(r.report().error.rms));
}

TEST(FitJob, NonPlanarCloudRefusesPolarMethod) {
  FitJobOptions o;
  o.method = FitJobMethod::polar;
  try {
    run_fit_job(vase_cloud(500, 0.0, 1), "vase", o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("planar"), std::string::npos) << e.what();
  }
}

TEST(FitJob, AProfileWithItsBoreIsTwoLoops) {
  // The bundled cam scan with its 8 mm bore: rays from the centre of the whole cloud (not the
  // bore's) cross the contour and the bore. Named as two loops, with their radii, in one line.
  const std::filesystem::path scan =
      std::filesystem::path(POLARFORM_SOURCE_DIR) / "examples/scans/cam_profile.xyz";
  try {
    run_fit_job(scan);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(
        std::string(e.what()),
        scan.string() +
            ": polar curve fit: two loops found (radius about 50 mm around the centre, "
            "radius about 8 mm around (12.5, -7.25)): use scan-cam, or remove the inner loop");
  }
}

// A planar profile r = 30 + 2 cos 3θ (σ = 0.01 mm radially) in the plane z = 4, 3000 points, and
// five points moved radially by ±4 mm: the last five.
Eigen::Matrix3Xd profile_with_outliers(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> T(0, 2 * kPi);
  std::normal_distribution<double> N(0, 0.01);
  Eigen::Matrix3Xd p(3, 3005);
  for (Eigen::Index k = 0; k < p.cols(); ++k) {
    const double t = T(rng), r = 30 + 2 * std::cos(3 * t) +
                                 (k < 3000 ? N(rng)
                                  : k % 2  ? 4.0
                                           : -4.0);
    p.col(k) << r * std::cos(t), r * std::sin(t), 4.0;
  }
  return p;
}

TEST(FitJob, OutliersAreRefusedOrRejectedAsAsked) {
  const Eigen::Matrix3Xd p = profile_with_outliers(9);
  try {
    run_fit_job(p, "spiky.xyz");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind("spiky.xyz: polar curve fit: 5 outliers of 3005 points at > 8 σ", 0), 0u)
        << m;
    EXPECT_NE(m.find("): rerun with --reject-outliers"), std::string::npos) << m;
  }
  FitJobOptions o;
  o.reject_outliers = true;
  o.ctrl = std::pair{24, 24};  // a curve uses the second: 24 control values follow the lobes
  const FitJobResult r = run_fit_job(p, "spiky.xyz", o);
  EXPECT_EQ(r.method, "polar");
  EXPECT_TRUE(r.reject_outliers);
  const FitReport& rep = r.report();
  EXPECT_EQ(rep.outliers.count, 5u);
  EXPECT_EQ(rep.error.count, 3000u);
  EXPECT_NEAR(rep.error.rms, 0.01, 0.001);
  EXPECT_NEAR(rep.outliers.largest, 4.0, 0.05);
  EXPECT_TRUE(r.warnings.empty());
  // A fit project carries the option.
  FitProject project;
  project.reject_outliers = true;
  EXPECT_TRUE(fit_job_options(project).reject_outliers);
}

// Points on the sphere of radius 25 about the origin with polar angle φ ≥ phi0, area-uniform.
Eigen::Matrix3Xd sphere_from(double phi0, int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> C(-1.0, std::cos(phi0)), T(0, 2 * kPi);
  Eigen::Matrix3Xd p(3, n);
  for (int k = 0; k < n; ++k) {
    const double c = C(rng), s = std::sqrt(1 - c * c), t = T(rng);
    p.col(k) << 25 * s * std::cos(t), 25 * s * std::sin(t), 25 * c;
  }
  return p;
}

// A G1 pole over a 25° hole is extrapolated, and the job says so; scanned to the poles, no
// warning.
TEST(FitJob, AnExtrapolatedPoleIsWarnedAbout) {
  FitJobOptions o;
  o.method = FitJobMethod::spherical;
  o.pole = PoleTreatment::g1;
  o.center = Eigen::Vector3d::Zero();
  o.axis = Eigen::Vector3d::UnitZ();
  const FitJobResult gap = run_fit_job(sphere_from(25 * kPi / 180, 4000, 3), "gap", o);
  ASSERT_EQ(gap.warnings.size(), 1u);
  const std::string& w = gap.warnings[0];
  EXPECT_EQ(w.rfind("spherical fit: the north pole is extrapolated: no data within 10° of it (the "
                    "nearest point is 25.",
                    0),
            0u)
      << w;
  const FitJobResult full = run_fit_job(sphere_from(0.0, 4000, 4), "full", o);
  EXPECT_TRUE(full.warnings.empty());
}

TEST(FitJob, BadOptionsAreInputErrors) {
  FitJobOptions o;
  o.ctrl = std::pair{10, 10};
  o.tolerance = 0.1;
  EXPECT_THROW(run_fit_job(sphere_cloud(200, 5.0, Eigen::Vector3d::Zero(), 1), "s", o), InputError);
  FitJobOptions cap;
  cap.pole = PoleTreatment::cap;
  cap.closure = Closure::open;
  EXPECT_THROW(run_fit_job(sphere_cloud(200, 5.0, Eigen::Vector3d::Zero(), 1), "s", cap),
               InputError);
}

}  // namespace
}  // namespace polarform
