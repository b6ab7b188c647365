// Design recovery from scans (designers/scan/design_recovery.h and its parts): laws fitted to
// exact motions give back their boundaries, lift and SCCA fractions; scans of the example cams
// and of random designs (σ = 2–10 µm, 2,000–20,000 points, random phase) give back every motion's
// law, boundaries within 0.5°, lifts within 3σ and a re-designed profile within 3σ of the scan;
// the resolution tells a fine scan's jerk from a coarse scan's noise.
#include "designers/scan/design_recovery.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "designers/cam/contour_polar_function.h"
#include "designers/scan/law_fit.h"
#include "designers/scan/motion_resolution.h"
#include "src/error.h"
#include "src/units.h"
#include "tests/support/designers/example_cams.h"
#include "tests/support/designers/random_cams.h"
#include "tests/support/designers/synthetic_scans.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

// a − b reduced to (−π, π].
double angle_difference(double a, double b) { return std::remainder(a - b, 2 * kPi); }

ScannedCam scan_of(const PlateCam& cam, double sigma, int points, double phase, unsigned seed) {
  CamScanSetup setup;
  setup.sigma = sigma;
  setup.contour_points = points;
  setup.phase = phase;
  setup.seed = seed;
  ScannedCamOptions o;
  o.follower = cam.follower();
  o.rotation = cam.rotation();
  return analyse_scanned_cam(cam_profile_scan(cam, setup), o);
}

// How a recovered design matches the true one.
struct Match {
  int motions = 0, right_law = 0, distinct = 0, distinct_right = 0;
  double boundary_error = 0.0;  // largest, rad
  double lift_error = 0.0;      // largest |Δlift| / σ
};

// Max |Δs| between two standard laws over the same boundaries and lift, in units of the lift.
double law_separation(MotionLaw a, MotionLaw b) {
  double worst = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    double sa, sb;
    standard_law(a, i / 1000.0, 0, &sa);
    standard_law(b, i / 1000.0, 0, &sb);
    worst = std::max(worst, std::abs(sa - sb));
  }
  return worst;
}

// Each true rise and return against the recovered motion that starts nearest to it (scan angle =
// design angle − σ·phase for a scan of the cam turned by phase).
void match(const PlateCam& cam, double phase, const RecoveredDesign& r, double sigma, Match& m) {
  const double shift = cam.sense() * phase;
  for (const MotionSegment& seg : cam.program().segments()) {
    const SegmentSpec& t = seg.spec();
    if (t.kind == SegmentKind::Dwell) continue;
    const IdentifiedMotion* best = nullptr;
    for (const IdentifiedMotion& im : r.motions)
      if (!best || std::abs(angle_difference(im.law().start, t.start - shift)) <
                       std::abs(angle_difference(best->law().start, t.start - shift)))
        best = &im;
    ASSERT_NE(best, nullptr);
    const LawFit& f = best->law();
    ++m.motions;
    const bool right =
        f.shape.law == t.law || (t.law == MotionLaw::Scca && f.shape.law == MotionLaw::Scca);
    m.right_law += right;
    double separation = INFINITY;
    for (MotionLaw other :
         {MotionLaw::SimpleHarmonic, MotionLaw::Cycloidal, MotionLaw::ModifiedTrapezoid,
          MotionLaw::ModifiedSine, MotionLaw::Polynomial345, MotionLaw::Polynomial4567})
      if (other != t.law && is_standard_law(t.law))
        separation = std::min(separation, t.lift * law_separation(t.law, other));
    if (separation > 3 * sigma) ++m.distinct, m.distinct_right += right;
    EXPECT_EQ(best->kind, t.kind);
    m.boundary_error =
        std::max({m.boundary_error, std::abs(angle_difference(f.start, t.start - shift)),
                  std::abs(angle_difference(f.end, t.end - shift))});
    m.lift_error = std::max(m.lift_error, std::abs(std::abs(f.lift) - t.lift) / sigma);
  }
}

// max |s_redesign − s_true| over the revolution, mm (design angle = true angle − σ·phase − the
// recovery's phase).
double redesign_motion_error(const PlateCam& cam, double phase, const RecoveredDesign& r) {
  const CamProgram redesign = make_program(r.design);
  double worst = 0.0;
  for (int i = 0; i < 3600; ++i) {
    const double theta = 2 * kPi * i / 3600;
    worst = std::max(
        worst, std::abs(redesign(theta - cam.sense() * phase - r.phase) - cam.program()(theta)));
  }
  return worst;
}

// examples/cams/scca_dynamics.xml: an SCCA (0.2, 0.6, 0.2) rise and a cycloidal return.
PlateCam scca_example() {
  CamDesign d = test::example_cam_design("roller");
  d.base_radius = 45;
  d.follower.roller_radius = 12;
  d.segments[1].law = MotionLaw::Scca;
  d.segments[1].scca = {0.2, 0.6, 0.2};
  d.segments[1].lift = d.segments[3].lift = 15;
  d.segments[3].law = MotionLaw::Cycloidal;
  d.segments[0].end = d.segments[1].start = 60 * kDeg;
  d.segments[1].end = d.segments[2].start = 170 * kDeg;
  d.segments[2].end = d.segments[3].start = 220 * kDeg;
  return make_plate_cam(d);
}

TEST(LawFit, ExactMotionsGiveBackBoundariesLiftAndSccaFractions) {
  const SccaParameters truth{0.2, 0.6, 0.2};
  LawWindow w;
  w.theta = Eigen::VectorXd::LinSpaced(2000, 0.5, 2.5);
  w.height.resize(w.theta.size());
  const SccaLaw law(truth);
  for (Eigen::Index k = 0; k < w.theta.size(); ++k) {
    double S[5];
    law.derivatives((w.theta[k] - 1.0) / 0.9, 0, S);
    w.height[k] = 40.0 + 12.0 * S[0];
  }
  LawFit guess;
  guess.start = 1.05, guess.end = 1.85, guess.level = 40.01, guess.lift = 11.9;
  const LawFit f = fit_law(w, LawShape{MotionLaw::Scca, {0.25, 0.5, 0.25}}, guess, 1e-3);
  EXPECT_NEAR(f.start, 1.0, 1e-6);
  EXPECT_NEAR(f.end, 1.9, 1e-6);
  EXPECT_NEAR(f.lift, 12.0, 1e-6);
  EXPECT_NEAR(f.shape.scca.b, 0.2, 1e-5);
  EXPECT_NEAR(f.shape.scca.d, 0.2, 1e-5);
  EXPECT_LT(f.rms(), 1e-7);
  // A wrong law leaves a residual far above the noise, a right one none.
  const LawFit cyc = fit_law(w, LawShape{MotionLaw::Cycloidal, {}}, guess, 1e-3);
  EXPECT_GT(cyc.rms(), 0.01);
}

TEST(LawFit, RefusesTooFewSamples) {
  LawWindow w;
  w.theta = Eigen::VectorXd::LinSpaced(10, 0, 1);
  w.height = w.theta;
  LawFit guess;
  guess.end = 1.0;
  EXPECT_THROW(fit_law(w, LawShape{}, guess, 1e-3), InputError);
}

TEST(DesignRecovery, ExampleCamsGiveBackTheirDesigns) {
  std::mt19937 rng(22);
  std::uniform_real_distribution<double> phase(0.0, 2 * kPi);
  Match total;
  double worst_redesign = 0.0;
  for (const std::string name :
       {"roller", "flat_faced", "offset_roller", "polynomial", "scca_dynamics"}) {
    SCOPED_TRACE(name);
    const PlateCam cam =
        name == "scca_dynamics" ? scca_example() : make_plate_cam(test::example_cam_design(name));
    const double sigma = 0.005, turn = phase(rng);
    const ScannedCam scan = scan_of(cam, sigma, 6000, turn, 7);
    const RecoveredDesign r = recover_design(scan);
    Match m;
    match(cam, turn, r, sigma, m);
    EXPECT_EQ(m.motions, 2);
    EXPECT_EQ(r.motions.size(), 2u);
    // The Hermite rise of "polynomial" is the 4-5-6-7 law, its return the 3-4-5 law.
    if (name != "polynomial") {
      EXPECT_EQ(m.right_law, m.motions);
    }
    EXPECT_LT(m.boundary_error, 0.1 * kDeg);
    EXPECT_LT(m.lift_error, 3.0);
    EXPECT_NEAR(r.design.base_radius, cam.base_radius(), 3 * sigma);
    EXPECT_LT(r.deviation.normal_stats.max, 3 * sigma);
    EXPECT_LT(redesign_motion_error(cam, turn, r), 3 * sigma);
    EXPECT_NEAR(r.deviation.point_normal_stats.rms, sigma, 0.1 * sigma);
    worst_redesign = std::max(worst_redesign, r.deviation.normal_stats.max);
    total.boundary_error = std::max(total.boundary_error, m.boundary_error);
    if (name == "polynomial") {
      for (const IdentifiedMotion& im : r.motions)
        EXPECT_EQ(im.law().shape.law, im.kind == SegmentKind::Rise ? MotionLaw::Polynomial4567
                                                                   : MotionLaw::Polynomial345);
    }
    if (name == "scca_dynamics") {
      const IdentifiedMotion& rise =
          r.motions[0].kind == SegmentKind::Rise ? r.motions[0] : r.motions[1];
      EXPECT_NEAR(rise.law().shape.scca.b, 0.2, 0.02);
      EXPECT_NEAR(rise.law().shape.scca.c, 0.6, 0.02);
    }
  }
  RecordProperty("max_boundary_error_deg", std::to_string(total.boundary_error / kDeg));
  RecordProperty("max_redesign_deviation_mm", std::to_string(worst_redesign));
}

// The laws beyond the six: a double-harmonic rise and its return (the rise played backwards, not
// its mirror image), and the cubic and constant-acceleration laws, come back as themselves.
TEST(DesignRecovery, DoubleHarmonicCubicAndConstantAccelerationAreIdentified) {
  const MotionLaw pairs[][2] = {{MotionLaw::DoubleHarmonic, MotionLaw::DoubleHarmonic},
                                {MotionLaw::Cubic, MotionLaw::ConstantAcceleration}};
  for (const auto& laws : pairs) {
    CamDesign d = test::example_cam_design("roller");
    d.segments[1].law = laws[0];
    d.segments[3].law = laws[1];
    const PlateCam cam = make_plate_cam(d);
    const double sigma = 0.004, turn = 0.7;
    const RecoveredDesign r = recover_design(scan_of(cam, sigma, 8000, turn, 11));
    Match m;
    match(cam, turn, r, sigma, m);
    EXPECT_EQ(m.motions, 2);
    EXPECT_EQ(m.right_law, 2) << motion_law_name(laws[0]) << ", " << motion_law_name(laws[1]);
    EXPECT_LT(m.boundary_error, 0.1 * kDeg);
    EXPECT_LT(m.lift_error, 3.0);
    EXPECT_LT(redesign_motion_error(cam, turn, r), 3 * sigma);
  }
}

TEST(DesignRecovery, RandomDesignsGiveBackLawsBoundariesAndLifts) {
  std::mt19937 rng(2022);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Match total;
  double worst_redesign_sigmas = 0.0;
  for (int design = 0; design < 17; ++design) {
    const CamDesign d = test::random_cam_design(rng);
    const PlateCam cam = make_plate_cam(d);
    const double sigma = 0.002 + 0.008 * U(rng), turn = 2 * kPi * U(rng);
    const int points = 2000 + static_cast<int>(18000 * U(rng) * U(rng));
    SCOPED_TRACE("design " + std::to_string(design) + ", σ " + std::to_string(sigma) + ", " +
                 std::to_string(points) + " points");
    const ScannedCam scanned = scan_of(cam, sigma, points, turn, 100 + design);
    const RecoveredDesign r = recover_design(scanned);
    const NominalComparison truth = compare_to_nominal(scanned, cam, 3600, -cam.sense() * turn);
    Match m;
    match(cam, turn, r, sigma, m);
    EXPECT_EQ(r.motions.size(), static_cast<std::size_t>(m.motions));
    // The re-designed profile is as close to the scan's fitted profile as the true design (whose
    // own deviation is the profile fit's bias where the curvature jumps), and its motion and base
    // radius are within 3σ of the truth's.
    EXPECT_LT(r.deviation.normal_stats.max, std::max(3 * sigma, 1.1 * truth.normal_stats.max));
    EXPECT_LT(r.deviation.point_normal_stats.rms, 1.05 * sigma);
    EXPECT_LT(redesign_motion_error(cam, turn, r), 3 * sigma);
    EXPECT_NEAR(r.design.base_radius, cam.base_radius(), 3 * sigma);
    worst_redesign_sigmas =
        std::max(worst_redesign_sigmas, redesign_motion_error(cam, turn, r) / sigma);
    total.motions += m.motions, total.right_law += m.right_law;
    total.distinct += m.distinct, total.distinct_right += m.distinct_right;
    total.boundary_error = std::max(total.boundary_error, m.boundary_error);
    total.lift_error = std::max(total.lift_error, m.lift_error);
  }
  EXPECT_GE(total.motions, 40);
  EXPECT_GE(total.distinct_right, 0.95 * total.distinct);
  EXPECT_LT(total.boundary_error, 0.5 * kDeg);
  EXPECT_LT(total.lift_error, 3.0);
  RecordProperty("motions", total.motions);
  RecordProperty("right_law", total.right_law);
  RecordProperty("distinct_right",
                 std::to_string(total.distinct_right) + "/" + std::to_string(total.distinct));
  RecordProperty("max_boundary_error_deg", std::to_string(total.boundary_error / kDeg));
  RecordProperty("max_lift_error_sigma", std::to_string(total.lift_error));
  RecordProperty("max_redesign_motion_error_sigma", std::to_string(worst_redesign_sigmas));
}

TEST(MotionResolution, FineScanResolvesJerkCoarseScanDoesNot) {
  const PlateCam cam = make_plate_cam(test::example_cam_design("roller"));
  const MotionResolution fine = resolve_motion(scan_of(cam, 0.002, 20000, 0.3, 3));
  const MotionResolution coarse = resolve_motion(scan_of(cam, 0.010, 2000, 0.3, 3));
  EXPECT_EQ(fine.resolved_order, 3);
  EXPECT_LT(coarse.resolved_order, 3);
  EXPECT_FALSE(coarse.derivatives[3].resolved);
  EXPECT_TRUE(coarse.derivatives[0].resolved);
  // The propagated noise of s is the fit's standard error in size, and grows with the order.
  EXPECT_GT(coarse.derivatives[3].noise, coarse.derivatives[2].noise);
  RecordProperty("fine_jerk_ratio",
                 std::to_string(fine.derivatives[3].signal / fine.derivatives[3].noise));
  RecordProperty("coarse_jerk_ratio",
                 std::to_string(coarse.derivatives[3].signal / coarse.derivatives[3].noise));
}

TEST(DesignRecovery, RefusesACamThatDoesNotMove) {
  CamDesign d = test::example_cam_design("roller");
  d.segments = {SegmentSpec{}};
  d.segments[0].kind = SegmentKind::Dwell;
  d.segments[0].end = 2 * kPi;
  const PlateCam circle = make_plate_cam(d);
  try {
    recover_design(scan_of(circle, 0.005, 3000, 0.0, 1));
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does not move"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace polarform
