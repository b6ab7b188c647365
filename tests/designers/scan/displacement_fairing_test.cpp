// Fairing the displacement recovered from scans (designers/scan/displacement_fairing.h and
// segmented_displacement.h) on synthetic scans of the example cams (tests/support: other laws,
// followers, noise levels and sample counts than the bundled roller scan of the scan-cam job test):
// the refit along the recovered design finds the boundaries with the laws' continuity, holds the
// dwells flat, and Farin's fairing after it cuts the rms error of the recovered acceleration
// against the nominal design by at least 2× while s moves by less than the scan's noise σ̂ and
// stays within σ̂ of the nominal.
#include "designers/scan/displacement_fairing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "designers/scan/nominal_comparison.h"
#include "designers/scan/segmented_displacement.h"
#include "src/number_text.h"
#include "tests/support/designers/example_cams.h"
#include "tests/support/designers/random_cams.h"
#include "tests/support/designers/synthetic_scans.h"

namespace polarform {
namespace {

constexpr double kDeg = std::numbers::pi / 180;

PlateCam example_cam(const std::string& name) {
  return make_plate_cam(test::example_cam_design(name));
}

// A 2D profile scan turned by 40°, aligned to its nominal (as scan-cam --nominal does).
ScannedCam scan_of(const PlateCam& cam, double sigma, int points, unsigned seed) {
  CamScanSetup setup;
  setup.sigma = sigma;
  setup.contour_points = points;
  setup.phase = 40 * kDeg;
  setup.seed = seed;
  ScannedCamOptions o;
  o.follower = cam.follower();
  o.rotation = cam.rotation();
  o.nominal = cam;
  return analyse_scanned_cam(cam_profile_scan(cam, setup), o);
}

struct Outcome {
  double a_before, a_after, s_error_after, noise;
  DisplacementFairing fairing;
};

Outcome fair(const PlateCam& cam, double sigma, int points, unsigned seed) {
  ScannedCam scan = scan_of(cam, sigma, points, seed);
  Outcome r;
  r.noise = scan.displacement.noise;
  r.a_before = compare_to_nominal(scan, cam).svaj_stats[2].rms;
  r.fairing = fair_scanned_displacement(scan, ProfileFairingOptions{});
  const NominalComparison after = compare_to_nominal(scan, cam);
  r.a_after = after.svaj_stats[2].rms;
  r.s_error_after = after.svaj_stats[0].max;
  return r;
}

void expect_faired_within_noise(const Outcome& r) {
  testing::Test::RecordProperty("a_rms_before", format_round_trip(r.a_before));
  testing::Test::RecordProperty("a_rms_after", format_round_trip(r.a_after));
  ASSERT_TRUE(r.fairing.refit) << r.fairing.refit_skipped;
  EXPECT_TRUE(r.fairing.refit->discrepancy_met);
  EXPECT_LE(r.a_after, r.a_before / 2);
  // The profile stays within the scan noise: s moved by less than σ̂ from the fit, and the faired
  // s is within σ̂ of the nominal's.
  EXPECT_LE(r.fairing.measured_deviation, r.noise);
  EXPECT_LE(r.fairing.measured_deviation, r.fairing.tolerance);
  EXPECT_LE(r.s_error_after, r.noise);
  EXPECT_FALSE(r.fairing.steps.empty());
}

TEST(DisplacementFairing, PiecesCarryTheRecoveredBoundariesAndTheLawsContinuity) {
  // offset_roller.xml: dwell, modified-trapezoid rise 60°–170° (C2 at both ends), dwell, simple
  // harmonic return 200°–330° (its acceleration jumps: C1), dwell.
  const ScannedCam scan = scan_of(example_cam("offset_roller"), 0.005, 3600, 3);
  const DisplacementPieces p = displacement_pieces(recover_design(scan));
  ASSERT_EQ(p.breaks.size(), 4u);
  ASSERT_EQ(p.dwells.size(), 2u);
  const double at[4] = {60, 170, 200, 330};
  const int continuity[4] = {2, 2, 1, 1};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(p.breaks[k].theta / kDeg, at[k], 0.05) << k;
    EXPECT_EQ(p.breaks[k].continuity, continuity[k]) << k;
  }
}

TEST(DisplacementFairing, RefitIsFlatOverTheDwellsAndMeetsTheDiscrepancy) {
  const ScannedCam scan = scan_of(example_cam("roller"), 0.005, 3600, 1);
  const DisplacementPieces p = displacement_pieces(recover_design(scan));
  const SegmentedDisplacement r = fit_segmented_displacement(scan.samples, p);
  EXPECT_TRUE(r.discrepancy_met);
  EXPECT_NEAR(r.rss, r.target_rss, 1e-6 * r.target_rss);
  EXPECT_EQ(r.dwells, 2u);
  // roller.xml dwells over 0°–90° and 180°–240°: s″ is zero there to round-off.
  for (double deg : {5.0, 45.0, 85.0, 185.0, 210.0, 235.0})
    EXPECT_NEAR(r.height.derivatives(deg * kDeg, 2)[2], 0.0, 1e-8) << deg;
  EXPECT_LT(r.dof, scan.displacement.dof);  // smoother than GCV's fit
}

// offset_roller.xml (modified trapezoid and simple harmonic, offset roller) with twice the
// bundled scan's noise and fewer points: 1.65 → 0.245 mm/rad² (6.7×) when measured.
TEST(DisplacementFairing, FarinHalvesTheAccelerationErrorOfANoisySparseScan) {
  expect_faired_within_noise(fair(example_cam("offset_roller"), 0.010, 2000, 3));
}

// flat_faced.xml (3-4-5 and modified sine, flat-faced follower, clockwise) with less noise and
// more points: 0.253 → 0.0386 mm/rad² (6.5×) when measured.
TEST(DisplacementFairing, FarinHalvesTheAccelerationErrorOfAFineScan) {
  expect_faired_within_noise(fair(example_cam("flat_faced"), 0.002, 10000, 2));
}

// Random designs (tests/support/designers/random_cams.h: two or four motions of the six standard
// laws at random boundaries, random followers) scanned with σ = 2, 5 or 10 µm and 2000 or 8000
// points: measured 2.6× (σ = 10 µm, 2000 points) to 48×. s may move from the GCV fit by more than
// σ̂ (up to 1.7 σ̂ where that fit is biased at steep motions), but always within the tolerance,
// and the faired s is within σ̂ of the design's.
TEST(DisplacementFairing, FarinHalvesTheAccelerationErrorOnRandomDesigns) {
  std::mt19937 rng(11);
  for (int i = 0; i < 8; ++i) {
    const PlateCam cam = make_plate_cam(test::random_cam_design(rng));
    const double sigma = i % 3 == 0 ? 0.010 : i % 3 == 1 ? 0.002 : 0.005;
    const Outcome r = fair(cam, sigma, i % 2 ? 2000 : 8000, 20 + static_cast<unsigned>(i));
    ASSERT_TRUE(r.fairing.refit) << i << ": " << r.fairing.refit_skipped;
    EXPECT_LE(r.a_after, r.a_before / 2) << i;
    EXPECT_LE(r.fairing.measured_deviation, r.fairing.tolerance) << i;
    EXPECT_LE(r.s_error_after, r.noise) << i;
  }
}

// A tolerance below what the refit moves s by: s is faired as fitted, and the report says why.
TEST(DisplacementFairing, TightToleranceFairsTheFitAsItIs) {
  ScannedCam scan = scan_of(example_cam("roller"), 0.005, 3600, 1);
  const BSplineFunction before = scan.displacement.height;
  const DisplacementFairing f =
      fair_scanned_displacement(scan, ProfileFairingOptions{FairingMethod::farin, 1e-4, 100});
  EXPECT_FALSE(f.refit);
  EXPECT_NE(f.refit_skipped.find("beyond the tolerance"), std::string::npos) << f.refit_skipped;
  EXPECT_EQ(f.refit_deviation, 0.0);
  EXPECT_LE(f.measured_deviation, 1e-4);
  EXPECT_EQ(scan.displacement.height.knots(), before.knots());
}

}  // namespace
}  // namespace polarform
