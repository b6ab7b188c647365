// Preset heads: their exact meridians lie on the defining circles and ellipses, their curvature is
// piecewise the reciprocal radii, and the jumps sit at the junctions and knuckle–crown joints.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/vessel/head_preset.h"
#include "designers/vessel/polar_curvature.h"
#include "src/error.h"

namespace polarform {
namespace {

using ::testing::HasSubstr;
constexpr double kPi = std::numbers::pi;

double curvature(const PolarFunction& f, double theta) {
  double d[3];
  f.derivatives(theta, 2, d);
  return polar_curvature(d[0], d[1], d[2]);
}

Eigen::Vector2d point(const PolarFunction& f, double theta) {
  return f(theta) * Eigen::Vector2d(std::cos(theta), std::sin(theta));
}

TEST(HeadPreset, Hemispherical) {
  const HeadShape h = head_shape({}, 500);
  EXPECT_EQ(h.name, "hemispherical");
  ASSERT_EQ(h.pieces.size(), 1u);
  EXPECT_EQ(h.depth, 500.0);
  for (int i = 0; i <= 18; ++i) EXPECT_EQ(h.profile(kPi * i / 18), 500.0);
  ASSERT_EQ(h.jumps.size(), 2u);
  EXPECT_EQ(h.jumps[0].theta, 0.0);
  EXPECT_EQ(h.jumps[0].kappa_before, 0.0);
  EXPECT_DOUBLE_EQ(h.jumps[0].kappa_after, 1.0 / 500);
  EXPECT_DOUBLE_EQ(h.jumps[1].kappa_before, 1.0 / 500);
  EXPECT_EQ(h.jumps[1].kappa_after, 0.0);
  EXPECT_EQ(h.profile.breakpoints, std::vector<double>{kPi / 2});
}

// 2:1 head of radius a = 500: depth b = 250, meridional curvature a/b² at the junction and b/a² at
// the apex.
TEST(HeadPreset, TwoToOneEllipsoidal) {
  const HeadShape h = head_shape({HeadKind::ellipsoidal, 2.0}, 500);
  EXPECT_EQ(h.name, "2:1 semi-ellipsoidal");
  EXPECT_NEAR(h.depth, 250.0, 1e-12);
  for (int i = 0; i <= 36; ++i) {
    const Eigen::Vector2d p = point(h.profile, kPi * i / 36);
    EXPECT_NEAR(std::pow(p.x() / 500, 2) + std::pow(p.y() / 250, 2), 1.0, 1e-14);
  }
  EXPECT_NEAR(curvature(h.profile, 0.0), 500.0 / (250.0 * 250.0), 1e-15);
  EXPECT_NEAR(curvature(h.profile, kPi / 2), 250.0 / (500.0 * 500.0), 1e-16);
  ASSERT_EQ(h.jumps.size(), 2u);
  EXPECT_NEAR(h.jumps[0].kappa_after, 0.008, 1e-15);
  EXPECT_NEAR(h.jumps[1].kappa_before, 0.008, 1e-15);
}

// ASME flanged-and-dished 100 %/6 % head, D = 1000: crown 1000, knuckle 60; the crown centre lies
// √(940² − 440²) below the junction plane, the depth is 1000 minus that.
TEST(HeadPreset, Torispherical100_6) {
  const HeadPreset preset = torispherical_100_6(500);
  EXPECT_DOUBLE_EQ(preset.crown, 1000.0);
  EXPECT_DOUBLE_EQ(preset.knuckle, 60.0);
  const HeadShape h = head_shape(preset, 500);
  EXPECT_EQ(h.name, "torispherical, crown 1000 mm, knuckle 60 mm");
  const double zc = -std::sqrt(940.0 * 940.0 - 440.0 * 440.0);
  EXPECT_NEAR(h.depth, 1000 + zc, 1e-10);
  EXPECT_NEAR(h.depth, 169.337614, 1e-6);
  ASSERT_EQ(h.pieces.size(), 3u);
  const double joint = h.pieces[1].start;
  EXPECT_NEAR(joint * 180 / kPi, 6.462471, 1e-6);
  EXPECT_DOUBLE_EQ(h.pieces[2].start, kPi - joint);
  for (int i = 0; i <= 20; ++i) {
    const double t1 = joint * i / 20, t2 = joint + (kPi / 2 - joint) * i / 20;
    EXPECT_NEAR((point(h.pieces[0], t1) - Eigen::Vector2d(440, 0)).norm(), 60.0, 1e-11);
    EXPECT_NEAR((point(h.pieces[1], t2) - Eigen::Vector2d(0, zc)).norm(), 1000.0, 1e-10);
    EXPECT_NEAR(curvature(h.pieces[0], t1), 1.0 / 60, 1e-13);
    EXPECT_NEAR(curvature(h.pieces[1], t2), 1.0 / 1000, 1e-15);
    EXPECT_NEAR(h.profile(kPi - t1), h.profile(t1), 1e-10);  // symmetric
  }
  double knuckle[2], crown[2];  // tangent at the joint: R and R' agree
  h.pieces[0].derivatives(joint, 1, knuckle);
  h.pieces[1].derivatives(joint, 1, crown);
  EXPECT_NEAR(knuckle[0], crown[0], 1e-10);
  EXPECT_NEAR(knuckle[1], crown[1], 1e-8);
  ASSERT_EQ(h.jumps.size(), 4u);
  const double expected[4][3] = {{0, 0, 1.0 / 60},
                                 {joint, 1.0 / 60, 1.0 / 1000},
                                 {kPi - joint, 1.0 / 1000, 1.0 / 60},
                                 {kPi, 1.0 / 60, 0}};
  for (int j = 0; j < 4; ++j) {
    EXPECT_DOUBLE_EQ(h.jumps[j].theta, expected[j][0]);
    EXPECT_NEAR(h.jumps[j].kappa_before, expected[j][1], 1e-13);
    EXPECT_NEAR(h.jumps[j].kappa_after, expected[j][2], 1e-13);
  }
  EXPECT_EQ(h.profile.breakpoints, (std::vector<double>{joint, kPi / 2, kPi - joint}));
}

TEST(HeadPreset, Torispherical80_10) {
  const HeadShape h = head_shape(torispherical_80_10(500), 500);
  EXPECT_EQ(h.name, "torispherical, crown 800 mm, knuckle 100 mm");
  EXPECT_NEAR(h.depth, 800 - std::sqrt(700.0 * 700.0 - 400.0 * 400.0), 1e-10);
  EXPECT_NEAR(curvature(h.profile, 0.01), 0.01, 1e-14);
  EXPECT_NEAR(curvature(h.profile, kPi / 2), 1.0 / 800, 1e-15);
}

TEST(HeadPreset, DerivativesOfEveryPresetAreConsistent) {
  for (const HeadPreset& preset :
       {HeadPreset{}, HeadPreset{HeadKind::ellipsoidal, 2.0}, HeadPreset{HeadKind::ellipsoidal, 1.3},
        torispherical_100_6(500), torispherical_80_10(500)}) {
    const HeadShape h = head_shape(preset, 500);
    for (const PolarFunction& piece : h.pieces)
      for (int i = 1; i < 10; ++i) {
        const double t = piece.start + (piece.end - piece.start) * i / 10, e = 1e-6;
        double d[4], p[4], m[4];
        piece.derivatives(t, 3, d);
        piece.derivatives(t + e, 3, p);
        piece.derivatives(t - e, 3, m);
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(d[k + 1], (p[k] - m[k]) / (2 * e), 2e-5 * (1 + std::abs(d[k + 1])))
              << h.name << " order " << k + 1 << " at " << t;
      }
  }
}

TEST(HeadPreset, TargetsSampleTheDistribution) {
  const HeadShape h = head_shape(torispherical_100_6(500), 500);
  const std::vector<CurvatureTarget> t = preset_targets(h, 90);
  ASSERT_EQ(t.size(), 90u);
  EXPECT_DOUBLE_EQ(t[0].theta, kPi / 180);
  EXPECT_NEAR(t[0].kappa, 1.0 / 60, 1e-13);  // 1° lies on the knuckle
  EXPECT_NEAR(t[45].kappa, 1.0 / 1000, 1e-15);
  EXPECT_EQ(t[45].weight, 1.0);
  EXPECT_THROW(preset_targets(h, 0), InputError);
}

TEST(HeadPreset, InvalidParametersNameThemselves) {
  const auto message = [](HeadPreset p, double radius) {
    try {
      head_shape(p, radius);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message({HeadKind::torispherical, 2, 1000, 500}, 500),
              HasSubstr("knuckle 500 mm, expected 0 < knuckle < radius = 500 mm"));
  EXPECT_THAT(message({HeadKind::torispherical, 2, 400, 60}, 500),
              HasSubstr("crown 400 mm, expected crown >= radius = 500 mm"));
  EXPECT_THAT(message({HeadKind::ellipsoidal, -2}, 500), HasSubstr("ellipsoidal ratio -2"));
  EXPECT_THAT(message({}, 0), HasSubstr("radius 0 mm, expected > 0"));
}

}  // namespace
}  // namespace polarform
