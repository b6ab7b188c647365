// Targets by arc length and meridian angle (target_placement.h): placed on a half spheroid and
// checked against its parametric form, and a synthesis whose targets are given by s or φ gives the
// same head as the same targets by θ.
#include "designers/vessel/target_placement.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/vessel/head_preset.h"
#include "designers/vessel/membrane_stress.h"
#include "designers/vessel/vessel_design.h"
#include "src/error.h"
#include "tests/support/designers/spheroid_meridian.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

// On x = a cos t, z = b sin t: the normal's angle against the axis is atan2(b cos t, a sin t) and
// the arc length from t = 0 is integrated independently (Simpson, 200 000 steps in t).
TEST(TargetPlacement, SpheroidAgainstItsParametricForm) {
  const double a = 500, b = 250;
  std::vector<CurvatureTarget> targets;
  for (double phi_deg : {80.0, 45.0, 10.0, 0.0, -30.0})
    targets.push_back({0.0, 0.0, 1.0, TargetPlace::meridian_angle, phi_deg * kPi / 180});
  for (double s : {50.0, 300.0, 600.0})
    targets.push_back({0.0, 0.0, 1.0, TargetPlace::arc_length, s});
  place_targets(targets, test::spheroid_meridian(a, b));
  const auto parameter = [&](double theta) {  // t of the point R(θ)(cosθ, sinθ)
    const double R = test::spheroid_meridian(a, b)(theta);
    return std::atan2(R * std::sin(theta) / b, R * std::cos(theta) / a);
  };
  for (const CurvatureTarget& t : targets) {
    const double u = parameter(t.theta);
    if (t.place == TargetPlace::meridian_angle) {
      EXPECT_NEAR(std::atan2(b * std::cos(u), a * std::sin(u)), t.position, 1e-12);
    } else {
      const int n = 200000;
      double s = 0.0;
      for (int i = 0; i <= n; ++i) {
        const double v = u * i / n, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        s += w * std::hypot(a * std::sin(v), b * std::cos(v));
      }
      s *= u / n / 3;
      EXPECT_NEAR(s, t.position, 1e-9 * t.position);
    }
  }
  std::vector<CurvatureTarget> beyond = {{0.0, 0.0, 1.0, TargetPlace::arc_length, 1e5}};
  try {
    place_targets(beyond, test::spheroid_meridian(a, b));
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("curvature target 1 at s = 100000 mm is not on the head"),
              std::string::npos)
        << e.what();
  }
}

// The 2:1 ellipsoidal head's curvature at 48 angles (ends R'' from its curvature), given by θ and
// then by the s and φ that head has there: the placement rounds put every target within 2e-6
// rad of its θ (measured 6.4e-7; the rounds stop below 1e-6) and the heads agree to 1e-6 of R.
TEST(TargetPlacement, TargetsBySOrPhiGiveTheHeadOfTheirTheta) {
  VesselDesign d;
  d.radius = 500, d.length = 1500, d.thickness = 10, d.pressure = 2;
  const HeadShape ellipse = head_shape(HeadPreset{HeadKind::ellipsoidal, 2.0}, 500);
  d.targets = preset_targets(ellipse, 48);
  d.end_a = d.end_b = EndCondition{500.0, 0.0, 500.0 - 4 / 500.0 * 500 * 500};
  d.synthesis.symmetric = true;
  const VesselSolution by_theta = solve_vessel(d);
  EXPECT_EQ(by_theta.placement_rounds, 1);
  VesselDesign by_place = d;
  for (std::size_t k = 0; k < d.targets.size(); ++k) {
    CurvatureTarget& t = by_place.targets[k];
    double r[2];
    by_theta.profile.derivatives(t.theta, 1, r);
    if (k % 2 == 0) {
      t.place = TargetPlace::arc_length;
      t.position = arc_length(by_theta.profile, 0.0, t.theta, 64);
    } else {
      t.place = TargetPlace::meridian_angle;
      t.position = kPi - t.theta - std::atan2(r[0], r[1]);
    }
    t.theta = 0.0;  // forgotten: the placement must find it
  }
  const VesselSolution placed = solve_vessel(by_place);
  EXPECT_GT(placed.placement_rounds, 2);
  RecordProperty("placement_rounds", placed.placement_rounds);
  for (std::size_t k = 0; k < d.targets.size(); ++k)
    EXPECT_NEAR(placed.synthesis.targets[k].theta, d.targets[k].theta, 2e-6) << k;
  for (int i = 0; i <= 180; ++i)
    EXPECT_NEAR(placed.profile(i * kPi / 180), by_theta.profile(i * kPi / 180), 1e-6 * 500) << i;
}

}  // namespace
}  // namespace polarform
