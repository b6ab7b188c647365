// The minimum-peak-stress head of a given depth (stress_optimal_head.h) against the standard heads
// of that depth (head_depth_comparison.h): membrane stresses measured at their exact extrema.
#include "designers/vessel/stress_optimal_head.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/vessel/head_depth_comparison.h"
#include "designers/vessel/head_preset.h"
#include "designers/vessel/polar_curvature.h"
#include "designers/vessel/vessel_design.h"
#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(TorisphericalOfDepth, ApexAtTheDepthAndStandardFormsRecovered) {
  const double a = 1000.0;
  for (const HeadPreset& p : {torispherical_100_6(a), torispherical_80_10(a)}) {
    const HeadShape shape = head_shape(p, a);
    const HeadPreset back = torispherical_of_depth(a, shape.depth, p.knuckle);
    EXPECT_NEAR(back.crown, p.crown, 1e-9 * a);
  }
  const HeadPreset q = torispherical_of_depth(a, 500.0, 340.0);
  EXPECT_NEAR(head_shape(q, a).depth, 500.0, 1e-9);
  EXPECT_THROW(torispherical_of_depth(a, 300.0, 400.0), InputError);  // knuckle deeper than head
  EXPECT_THROW(torispherical_of_depth(a, 300.0, 300.0), InputError);
}

// Measured (a = 1000 mm, t = 10 mm, p = 1 MPa, defaults): peak 85.64 MPa at the 2:1 depth against
// the ellipse's 100 (p a / t), the 17 % torisphere's 288.5 and the 6 % torisphere's 603.0.
TEST(StressOptimalHead, TwoToOneDepthBeatsTheEllipseAndTheTorisphericalHeads) {
  const double a = 1000.0, depth = 500.0;
  const VesselLoad load{a, 2000.0, 10.0, 1.0};
  const StressOptimalHead head = minimum_peak_stress_head(a, depth);
  const PolarFunction f = head_polar_function(head.profile);
  EXPECT_NEAR(f(0.0), a, 1e-9 * a);
  EXPECT_NEAR(f(kPi / 2), depth, 1e-9 * a);
  double d0[3];
  f.derivatives(0.0, 1, d0);
  EXPECT_NEAR(d0[1], 0.0, 1e-9 * a);  // tangent to the cylinder
  for (int i = 0; i <= 720; ++i) {    // no inflection, symmetric
    const double theta = kPi * i / 720;
    double d[3];
    f.derivatives(theta, 2, d);
    EXPECT_GE(polar_curvature(d[0], d[1], d[2]), -1e-9) << theta;
    EXPECT_NEAR(f(theta), f(kPi - theta), 1e-9 * a);
  }
  const HeadStressSummary designed = head_stress_summary("designed", f, load);
  const DepthComparison standard = standard_heads_of_depth(depth, load);
  ASSERT_EQ(standard.references.size(), 3u);
  EXPECT_TRUE(standard.missing.empty());
  const double ellipse = standard.references[0].peak_stress;
  EXPECT_NEAR(ellipse, load.pressure * a / load.thickness, 1e-9 * ellipse);  // p a / t
  // The sampled peak the optimiser sees against the exact extrema: within 0.2 %.
  EXPECT_NEAR(head.peak_radius * load.pressure / load.thickness, designed.peak_stress,
              2e-3 * designed.peak_stress);
  EXPECT_LT(designed.peak_stress, 0.9 * ellipse);
  EXPECT_LT(designed.peak_stress, 0.35 * standard.references[2].peak_stress);  // 17 % knuckle
  EXPECT_LT(designed.peak_stress, 0.15 * standard.references[1].peak_stress);  // 6 % knuckle
}

// The design never loses to the ellipse of its depth, shallow or deep; at the hemisphere's depth
// it is the hemisphere (p a / 2t everywhere).
TEST(StressOptimalHead, NeverAboveTheEllipseOfItsDepth) {
  const double a = 800.0;
  const VesselLoad load{a, 1000.0, 8.0, 2.0};
  for (const double share : {0.25, 0.33, 0.4, 0.6, 0.8, 1.0, 1.5}) {
    const double depth = share * a;
    const HeadStressSummary designed = head_stress_summary(
        "designed", head_polar_function(minimum_peak_stress_head(a, depth).profile), load);
    const double ellipse = standard_heads_of_depth(depth, load).references[0].peak_stress;
    EXPECT_LE(designed.peak_stress, ellipse * (1 + 1e-6)) << depth;
    if (share == 1.0) {
      EXPECT_NEAR(designed.peak_stress, load.pressure * a / (2 * load.thickness), 1e-6 * ellipse);
    }
  }
}

TEST(StressOptimalHead, CurvatureContinuousJunctionWhenAsked) {
  const double a = 1000.0;
  StressOptimalSettings settings;
  settings.junction_curvature = 0.0;
  const StressOptimalHead head = minimum_peak_stress_head(a, 500.0, settings);
  const Eigen::VectorXd d = head.profile.derivatives(0.0, 2);
  EXPECT_NEAR(polar_curvature(d(0), d(1), d(2)), 0.0, 1e-9 / a);
  const VesselLoad load{a, 2000.0, 10.0, 1.0};
  const HeadStressSummary s = head_stress_summary("c2", head_polar_function(head.profile), load);
  EXPECT_NEAR(s.junction_curvature, 0.0, 1e-9 / a);
  EXPECT_GE(s.peak_stress, load.pressure * a / load.thickness * (1 - 1e-6));  // hoop p a/t there
}

TEST(StressOptimalHead, RejectsBadInput) {
  EXPECT_THROW(minimum_peak_stress_head(0.0, 1.0), InputError);
  EXPECT_THROW(minimum_peak_stress_head(100.0, 0.0), InputError);
  EXPECT_THROW(minimum_peak_stress_head(100.0, 401.0), InputError);
  StressOptimalSettings s;
  s.ordinates = 5;
  EXPECT_THROW(minimum_peak_stress_head(100.0, 50.0, s), InputError);
}

}  // namespace
}  // namespace polarform
