// Head measures against an independent integration: the preset heads' exact polar meridians R(θ)
// (head_preset) and their offsets by t along the normal, integrated as π∫x² dz and 2π∫x ds by
// composite Simpson over each analytic piece; printed values from a 30-digit quadrature (mpmath);
// the special cases that are hemispheres; the bad inputs.
#include "designers/vessel/head_measures.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "designers/vessel/head_preset.h"
#include "designers/vessel/polar_curvature.h"
#include "src/error.h"

namespace polarform {
namespace {

using ::testing::HasSubstr;
constexpr double kPi = std::numbers::pi;

// π∫x² dz and 2π∫x ds over the meridian offset by t from θ = 0 (junction) to π/2 (apex): with
// p(θ) = R(θ)(cos θ, sin θ), outward normal n and curvature κ, the offset q = p + t·n has
// q' = (1 + κt)·p'. Composite Simpson with 20000 intervals per piece.
HeadMeasures integrated(const HeadShape& shape, double t) {
  HeadMeasures sum;
  for (const PolarFunction& piece : shape.pieces) {
    const double a = piece.start, b = std::min(piece.end, kPi / 2);
    if (a >= b) continue;
    const int n = 20000;
    for (int i = 0; i <= n; ++i) {
      const double theta = a + (b - a) * i / n;
      double d[3];
      piece.derivatives(theta, 2, d);
      const double c = std::cos(theta), s = std::sin(theta);
      const double px = d[0] * c;
      const double dx = d[1] * c - d[0] * s, dz = d[1] * s + d[0] * c;
      const double speed = std::hypot(dx, dz), grow = 1 + t * polar_curvature(d[0], d[1], d[2]);
      const double qx = px + t * dz / speed;
      const double w = (i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0) * (b - a) / (3.0 * n);
      sum.volume += w * kPi * qx * qx * grow * dz;
      sum.area += w * 2 * kPi * qx * grow * speed;
    }
  }
  return sum;
}

double relative(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

const HeadPreset kHemisphere{};
const HeadPreset kTwoToOne{HeadKind::ellipsoidal, 2.0};

TEST(HeadMeasures, Hemisphere) {
  const HeadMeasures m = hemispherical_head_measures(500);
  EXPECT_NEAR(m.volume, 2.0 / 3 * kPi * 1.25e8, 1e-6);
  EXPECT_NEAR(m.volume, 261799387.7991494, 1e-6);
  EXPECT_NEAR(m.area, 2 * kPi * 250000, 1e-9);  // 1570796.326795
  const HeadMeasures n = integrated(head_shape(kHemisphere, 500), 0.0);
  EXPECT_LT(relative(m.volume, n.volume), 1e-12);
  EXPECT_LT(relative(m.area, n.area), 1e-12);
}

// 2:1, a = 500, b = 250: V = πD³/24 and A = 1083985.337918 mm² (the handbooks' 1.084·D²).
TEST(HeadMeasures, TwoToOneEllipsoidal) {
  const HeadMeasures m = ellipsoidal_head_measures(500, 250);
  EXPECT_NEAR(m.volume, kPi * 1e9 / 24, 1e-6);
  EXPECT_NEAR(m.volume, 130899693.8995747, 1e-6);
  EXPECT_NEAR(m.area, 1083985.337918131, 1e-8);
  const HeadMeasures n = integrated(head_shape(kTwoToOne, 500), 0.0);
  EXPECT_LT(relative(m.volume, n.volume), 1e-12);
  EXPECT_LT(relative(m.area, n.area), 1e-12);
}

// Prolate (deeper than its radius) a = 300, b = 500: A = 828965.3096824 mm².
TEST(HeadMeasures, ProlateEllipsoidal) {
  const HeadMeasures m = ellipsoidal_head_measures(300, 500);
  EXPECT_NEAR(m.volume, 2.0 / 3 * kPi * 300 * 300 * 500, 1e-6);  // 94247779.6077
  EXPECT_NEAR(m.area, 828965.3096823584, 1e-8);
  const HeadMeasures n = integrated(head_shape({HeadKind::ellipsoidal, 0.6}, 300), 0.0);
  EXPECT_LT(relative(m.volume, n.volume), 1e-12);
  EXPECT_LT(relative(m.area, n.area), 1e-12);
}

TEST(HeadMeasures, EllipsoidsAgreeWithTheMeridianIntegral) {
  for (const double ratio : {3.0, 2.0, 1.3, 1.0 + 1e-6, 1.0, 1.0 - 1e-6, 0.8, 0.5, 0.25}) {
    const double radius = 400, depth = radius / ratio;
    const HeadMeasures m = ellipsoidal_head_measures(radius, depth);
    const HeadMeasures n = integrated(head_shape({HeadKind::ellipsoidal, ratio}, radius), 0.0);
    EXPECT_LT(relative(m.volume, n.volume), 1e-11) << ratio;
    EXPECT_LT(relative(m.area, n.area), 1e-11) << ratio;
  }
}

// b = a is the hemisphere, and the area is continuous through it from both sides.
TEST(HeadMeasures, EllipsoidOfEqualAxesIsTheHemisphere) {
  const HeadMeasures hemisphere = hemispherical_head_measures(500);
  const HeadMeasures equal = ellipsoidal_head_measures(500, 500);
  EXPECT_DOUBLE_EQ(equal.volume, hemisphere.volume);
  EXPECT_DOUBLE_EQ(equal.area, hemisphere.area);
  for (const double depth : {500 * (1 - 1e-12), 500 * (1 + 1e-12)}) {
    EXPECT_LT(relative(ellipsoidal_head_measures(500, depth).area, hemisphere.area), 1e-11);
    EXPECT_LT(
        relative(ellipsoidal_metal_volume(500, depth, 10), hemispherical_metal_volume(500, 10)),
        1e-11);
  }
}

// ASME 100 %/6 % head on R = 500 (crown 1000, knuckle 60): depth 169.3376137 mm,
// V = 80999004.29 mm³ (0.0810·D³), A = 930582.8296 mm².
TEST(HeadMeasures, Torispherical100_6) {
  EXPECT_NEAR(torispherical_depth(500, 1000, 60), 169.3376137081925, 1e-10);
  EXPECT_NEAR(torispherical_depth(500, 1000, 60), 1000 - std::sqrt(940.0 * 940 - 440.0 * 440),
              1e-12);
  const HeadMeasures m = torispherical_head_measures(500, 1000, 60);
  EXPECT_NEAR(m.volume, 80999004.29115162, 1e-5);
  EXPECT_NEAR(m.area, 930582.8296205793, 1e-7);
  const HeadShape shape = head_shape(torispherical_100_6(500), 500);
  EXPECT_NEAR(torispherical_depth(500, 1000, 60), shape.depth, 1e-10);
  const HeadMeasures n = integrated(shape, 0.0);
  EXPECT_LT(relative(m.volume, n.volume), 1e-12);
  EXPECT_LT(relative(m.area, n.area), 1e-12);
}

// 80 %/10 % on R = 500: depth 225.5437353 mm, V = 109883968.2 mm³, A = 1014680.340 mm².
TEST(HeadMeasures, Torispherical80_10) {
  EXPECT_NEAR(torispherical_depth(500, 800, 100), 225.5437353461971, 1e-10);
  const HeadMeasures m = torispherical_head_measures(500, 800, 100);
  EXPECT_NEAR(m.volume, 109883968.2020523, 1e-5);
  EXPECT_NEAR(m.area, 1014680.339734849, 1e-7);
}

TEST(HeadMeasures, TorisphericalHeadsAgreeWithTheMeridianIntegral) {
  const double proportions[][2] = {{1000, 60}, {800, 100}, {2000, 30}, {510, 20},
                                   {600, 499}, {5000, 5},  {1e4, 450}};
  for (const auto& [crown, knuckle] : proportions) {
    const HeadShape shape = head_shape({HeadKind::torispherical, 2.0, crown, knuckle}, 500);
    const HeadMeasures m = torispherical_head_measures(500, crown, knuckle);
    const HeadMeasures n = integrated(shape, 0.0);
    EXPECT_LT(relative(m.volume, n.volume), 1e-11) << crown << " " << knuckle;
    EXPECT_LT(relative(m.area, n.area), 1e-11) << crown << " " << knuckle;
    EXPECT_NEAR(torispherical_depth(500, crown, knuckle), shape.depth, 1e-10);
  }
}

// A crown of the vessel's radius is the hemisphere whatever the knuckle (the knuckle arc shrinks
// to the junction point), and so is a knuckle tending to the radius under any crown.
TEST(HeadMeasures, TorisphericalLimitsAreTheHemisphere) {
  const HeadMeasures hemisphere = hemispherical_head_measures(500);
  for (const double knuckle : {1.0, 60.0, 250.0, 499.0}) {
    const HeadMeasures m = torispherical_head_measures(500, 500, knuckle);
    EXPECT_LT(relative(m.volume, hemisphere.volume), 1e-15) << knuckle;
    EXPECT_LT(relative(m.area, hemisphere.area), 1e-15) << knuckle;
    EXPECT_DOUBLE_EQ(torispherical_depth(500, 500, knuckle), 500.0);
  }
  const double knuckle = 500 * (1 - 1e-10);
  for (const double crown : {500.0, 1000.0, 1e5}) {
    const HeadMeasures m = torispherical_head_measures(500, crown, knuckle);
    EXPECT_LT(relative(m.volume, hemisphere.volume), 1e-9) << crown;
    EXPECT_LT(relative(m.area, hemisphere.area), 1e-9) << crown;
    EXPECT_NEAR(torispherical_depth(500, crown, knuckle), 500.0, 1e-6) << crown;
  }
  EXPECT_LT(
      relative(torispherical_metal_volume(500, 500, 60, 10), hemispherical_metal_volume(500, 10)),
      1e-14);
}

TEST(HeadMeasures, Cylinder) {
  const HeadMeasures m = cylinder_measures(500, 1500);
  EXPECT_NEAR(m.volume, kPi * 500 * 500 * 1500, 1e-5);  // 1178097245.0962
  EXPECT_NEAR(m.area, 2 * kPi * 500 * 1500, 1e-8);      // 4712388.980385
  EXPECT_NEAR(cylinder_metal_volume(500, 1500, 10), kPi * (510.0 * 510 - 500.0 * 500) * 1500,
              1e-6);  // 47595128.70
}

// Metal between the inner surface and its offset by t: the hemisphere's by its closed form, the
// others against the offset meridian's integral, and printed values from the 30-digit quadrature.
TEST(HeadMeasures, MetalVolumes) {
  EXPECT_NEAR(hemispherical_metal_volume(500, 10), 2.0 / 3 * kPi * (510.0 * 510 * 510 - 1.25e8),
              1e-6);
  EXPECT_NEAR(ellipsoidal_metal_volume(500, 250, 10), 11110428.21588225, 1e-6);
  EXPECT_NEAR(ellipsoidal_metal_volume(300, 500, 8), 6783025.821717380, 1e-6);
  EXPECT_NEAR(torispherical_metal_volume(500, 1000, 60, 10), 9564116.956334383, 1e-6);
  const HeadPreset presets[] = {kHemisphere,
                                kTwoToOne,
                                {HeadKind::ellipsoidal, 1.3},
                                {HeadKind::ellipsoidal, 0.6},
                                {HeadKind::ellipsoidal, 3.0},
                                torispherical_100_6(500),
                                torispherical_80_10(500),
                                {HeadKind::torispherical, 2.0, 2000, 30}};
  for (const HeadPreset& preset : presets)
    for (const double t : {0.5, 10.0, 80.0}) {
      const HeadShape shape = head_shape(preset, 500);
      const double metal = integrated(shape, t).volume - integrated(shape, 0.0).volume;
      EXPECT_LT(relative(head_metal_volume(preset, 500, t), metal), 1e-10)
          << shape.name << " t = " << t;
    }
}

// π∫x² dz of the arc of radius t about a centre at x = cx whose normal turns from φ0 to φ1
// (composite Simpson): the offset's fan at a corner of the meridian.
double fan_volume(double cx, double t, double phi0, double phi1) {
  const int n = 20000;
  double sum = 0;
  for (int i = 0; i <= n; ++i) {
    const double phi = phi0 + (phi1 - phi0) * i / n, x = cx + t * std::cos(phi);
    const double w = (i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0) * (phi1 - phi0) / (3.0 * n);
    sum += w * kPi * x * x * t * std::cos(phi);
  }
  return sum;
}

// Conical heads against the meridian integral; the offset adds the fans at its corners: the apex
// (normal from α to 90°) and, without a knuckle, the junction (normal from 0 to α).
TEST(HeadMeasures, ConicalHeadsAgreeWithTheMeridianIntegral) {
  const double cases[][2] = {{30, 60}, {30, 0}, {45, 100}, {10, 20}, {60, 0}, {80, 300}};
  for (const auto& [degrees, knuckle] : cases) {
    const double a = degrees * kPi / 180;
    const HeadPreset preset{HeadKind::conical, 2.0, 0.0, knuckle, a};
    const HeadShape shape = head_shape(preset, 500);
    const HeadMeasures m = conical_head_measures(500, a, knuckle);
    const HeadMeasures n = integrated(shape, 0.0);
    EXPECT_LT(relative(m.volume, n.volume), 1e-11) << degrees << " " << knuckle;
    EXPECT_LT(relative(m.area, n.area), 1e-11) << degrees << " " << knuckle;
    EXPECT_EQ(head_measures(preset, 500).volume, m.volume);
    for (const double t : {0.5, 10.0, 80.0}) {
      double outer = integrated(shape, t).volume + fan_volume(0.0, t, a, kPi / 2);
      if (knuckle == 0) outer += fan_volume(500, t, 0, a);
      EXPECT_LT(relative(conical_metal_volume(500, a, knuckle, t), outer - n.volume), 1e-10)
          << degrees << " " << knuckle << " t = " << t;
      EXPECT_EQ(head_metal_volume(preset, 500, t), conical_metal_volume(500, a, knuckle, t));
    }
  }
  // A plain cone: V = π R³ cot α / 3, A = π R²/sin α.
  EXPECT_NEAR(conical_head_measures(500, kPi / 6, 0).volume, kPi * 1.25e8 * std::sqrt(3.0) / 3,
              1e-6);
  EXPECT_NEAR(conical_head_measures(500, kPi / 6, 0).area, kPi * 250000 * 2, 1e-6);
}

// Flanged flat heads against the meridian integral (the offset of a smooth meridian needs no
// fan), the closed form V = π c² r + π² c r²/2 + 2π r³/3, A = π² r c + 2π r² + π c² written out
// here (c = R − r). (A 5 mm knuckle agrees with the closed form; its plate, R = r/sin θ from
// θ ≈ 0.6°, is too steep for the integral's 20000 Simpson steps: 2e-7.)
TEST(HeadMeasures, FlatHeadsAgreeWithTheMeridianIntegral) {
  for (const double r : {60.0, 40.0, 250.0}) {
    const HeadPreset preset{HeadKind::flat, 2.0, 0.0, r};
    const HeadShape shape = head_shape(preset, 500);
    const HeadMeasures m = flat_head_measures(500, r);
    const HeadMeasures n = integrated(shape, 0.0);
    const double c = 500 - r;
    EXPECT_LT(
        relative(m.volume, kPi * c * c * r + kPi * kPi * c * r * r / 2 + 2 * kPi * r * r * r / 3),
        1e-14)
        << r;
    EXPECT_LT(relative(m.area, kPi * kPi * r * c + 2 * kPi * r * r + kPi * c * c), 1e-14) << r;
    const HeadMeasures thin = flat_head_measures(500, 5);
    EXPECT_LT(relative(thin.volume, kPi * 495 * 495 * 5 + kPi * kPi * 495 * 12.5 + 250 * kPi / 3),
              1e-14);
    EXPECT_LT(relative(m.volume, n.volume), 1e-10) << r;
    EXPECT_LT(relative(m.area, n.area), 1e-10) << r;
    EXPECT_EQ(head_measures(preset, 500).volume, m.volume);
    for (const double t : {0.5, 10.0, 40.0}) {
      EXPECT_LT(relative(flat_metal_volume(500, r, t), integrated(shape, t).volume - n.volume),
                1e-9)
          << r << " t = " << t;
      EXPECT_EQ(head_metal_volume(preset, 500, t), flat_metal_volume(500, r, t));
    }
  }
  EXPECT_THROW(flat_head_measures(500, 0.0), InputError);
}

TEST(HeadMeasures, PresetsDispatchToTheirHeads) {
  EXPECT_EQ(head_measures(kHemisphere, 500).volume, hemispherical_head_measures(500).volume);
  EXPECT_EQ(head_measures(kTwoToOne, 500).area, ellipsoidal_head_measures(500, 250).area);
  EXPECT_EQ(head_measures(torispherical_80_10(500), 500).volume,
            torispherical_head_measures(500, 800, 100).volume);
  EXPECT_EQ(head_metal_volume(kTwoToOne, 500, 10), ellipsoidal_metal_volume(500, 250, 10));
  EXPECT_EQ(head_metal_volume(torispherical_100_6(500), 500, 10),
            torispherical_metal_volume(500, 1000, 60, 10));
  EXPECT_EQ(head_metal_volume(kHemisphere, 500, 10), hemispherical_metal_volume(500, 10));
}

// 1 m³ of steel at 7850 kg/m³; the 2:1 head above (D = 1000, t = 10): 87.2168615 kg.
TEST(HeadMeasures, Weight) {
  EXPECT_NEAR(metal_weight(1e9, 7850), 7850.0, 1e-9);
  EXPECT_NEAR(metal_weight(ellipsoidal_metal_volume(500, 250, 10), 7850), 87.21686149467566, 1e-9);
  EXPECT_EQ(metal_weight(0.0, 7850), 0.0);
}

TEST(HeadMeasures, BadInputNamesTheField) {
  const auto message = [](auto f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message([] { hemispherical_head_measures(0); }),
            "head measures: radius R = 0 mm, expected > 0");
  EXPECT_THAT(message([] { ellipsoidal_head_measures(500, -1); }),
              HasSubstr("depth b = -1 mm, expected > 0"));
  EXPECT_THAT(message([] { ellipsoidal_head_measures(NAN, 250); }),
              HasSubstr("radius a = nan mm, expected > 0"));
  EXPECT_EQ(message([] { torispherical_head_measures(500, 1000, 500); }),
            "head measures: torispherical knuckle radius r = 500 mm, expected 0 < r < R = 500 mm");
  EXPECT_THAT(message([] { torispherical_depth(500, 1000, 0); }),
              HasSubstr("knuckle radius r = 0 mm, expected 0 < r < R = 500 mm"));
  EXPECT_EQ(message([] { torispherical_head_measures(500, 400, 60); }),
            "head measures: torispherical crown radius L = 400 mm, expected L >= R = 500 mm");
  EXPECT_THAT(message([] { cylinder_measures(500, 0); }), HasSubstr("length = 0 mm, expected > 0"));
  EXPECT_THAT(message([] { torispherical_metal_volume(500, 1000, 60, 0); }),
              HasSubstr("thickness t = 0 mm, expected > 0"));
  EXPECT_THAT(message([] { torispherical_metal_volume(500, 1000, 500, 10); }),
              HasSubstr("knuckle radius r = 500 mm"));
  EXPECT_THAT(message([] {
                head_metal_volume({HeadKind::ellipsoidal, 0.0}, 500, 10);
              }),
              HasSubstr("ellipsoidal ratio radius/depth = 0, expected > 0"));
  EXPECT_THAT(message([] { metal_weight(-1, 7850); }),
              HasSubstr("metal volume = -1 mm³, expected >= 0"));
  EXPECT_THAT(message([] { metal_weight(1, 0); }), HasSubstr("density = 0 kg/m³, expected > 0"));
}

}  // namespace
}  // namespace polarform
