// The exact standard heads: degree-2 rational meridians on their closed forms (implicit equations
// evaluated here, independently of head_shape) to 1e-9 mm, tangent-continuous at their joints,
// with the ends, apex and depth of the head asked for, and revolved into (2, 2) surfaces.
#include "designers/vessel/exact_head.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "designers/vessel/vessel_surfaces.h"
#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

// Distance-like residual of a point to the head's closed form: circles by |p − c| − r (the nearer
// of knuckle and crown where both apply), the ellipse by its algebraic distance scaled to mm.
double closed_form_residual(const HeadPreset& h, double R, const Eigen::Vector2d& p) {
  switch (h.kind) {
    case HeadKind::hemispherical:
      return p.norm() - R;
    case HeadKind::ellipsoidal: {
      const double a = R, b = R / h.ratio;
      const double f = p.x() * p.x() / (a * a) + p.y() * p.y() / (b * b) - 1;
      const double grad = 2 * std::hypot(p.x() / (a * a), p.y() / (b * b));
      return f / grad;  // first-order distance
    }
    case HeadKind::torispherical: {
      const double rk = h.knuckle, rc = h.crown, kx = R - rk;
      const double zc = -std::sqrt((rc - rk) * (rc - rk) - kx * kx);
      // The crown where the point lies within the crown's cone (|x| below the joint's), else the
      // knuckle on the point's side.
      const double joint_x = rc * kx / (rc - rk);
      if (std::abs(p.x()) <= joint_x) return std::hypot(p.x(), p.y() - zc) - rc;
      return std::hypot(std::abs(p.x()) - kx, p.y()) - rk;
    }
    case HeadKind::conical: {
      // The cone: the line through the apex (0, z_A) at α to the axis, z_A from the knuckle's
      // tangent point written out here; below the tangent point's height, the knuckle circle.
      const double a = h.half_angle, rk = h.knuckle, kx = R - rk;
      const double tx = kx + rk * std::cos(a), tz = rk * std::sin(a);
      const double apex = tz + tx * std::cos(a) / std::sin(a);
      if (p.y() < tz - 1e-12) return std::hypot(std::abs(p.x()) - kx, p.y()) - rk;
      return std::abs(p.x()) * std::cos(a) + (p.y() - apex) * std::sin(a);
    }
    case HeadKind::flat: {
      // The plate z = r inside the knuckle's end |x| <= R − r, else the knuckle circle.
      const double rk = h.knuckle, kx = R - rk;
      if (std::abs(p.x()) <= kx) return p.y() - rk;
      return std::hypot(std::abs(p.x()) - kx, p.y()) - rk;
    }
  }
  return NAN;
}

struct Case {
  const char* name;
  HeadPreset preset;
  double radius;
  double depth;  // closed form
};

std::vector<Case> cases() {
  const double R = 500;
  const double tori_depth = 1000 - std::sqrt(940.0 * 940.0 - 440.0 * 440.0);
  const double tori_80_depth = 800 - std::sqrt(700.0 * 700.0 - 400.0 * 400.0);
  return {{"hemispherical", {HeadKind::hemispherical}, R, R},
          {"2:1 ellipsoidal", {HeadKind::ellipsoidal, 2.0}, R, R / 2},
          {"4:1 ellipsoidal", {HeadKind::ellipsoidal, 4.0}, R, R / 4},
          {"1.2:1 ellipsoidal", {HeadKind::ellipsoidal, 1.2}, R, R / 1.2},
          {"torispherical 100 %/6 %", torispherical_100_6(R), R, tori_depth},
          {"torispherical 80 %/10 %", torispherical_80_10(R), R, tori_80_depth},
          {"torispherical crown 700 knuckle 35",
           {HeadKind::torispherical, 2.0, 700, 35},
           400,
           700 - std::sqrt(665.0 * 665.0 - 365.0 * 365.0)}};
}

// Conical heads: half angle α in degrees, knuckle r; depth from the tangent point (closed form).
std::vector<Case> conical_cases() {
  std::vector<Case> out;
  for (const auto& [degrees, knuckle] : std::vector<std::pair<double, double>>{
           {30, 60}, {30, 0}, {45, 100}, {15, 30}, {60, 0}, {75, 200}}) {
    const double a = degrees * kPi / 180, kx = 500 - knuckle;
    const double tx = kx + knuckle * std::cos(a), tz = knuckle * std::sin(a);
    out.push_back(
        {"conical", {HeadKind::conical, 2.0, 0.0, knuckle, a}, 500, tz + tx / std::tan(a)});
  }
  return out;
}

// Flanged flat heads: knuckle r; the plate lies at the depth r.
std::vector<Case> flat_cases() {
  return {{"flat r 50", {HeadKind::flat, 2.0, 0.0, 50}, 500, 50},
          {"flat r 3", {HeadKind::flat, 2.0, 0.0, 3}, 500, 3},
          {"flat r 120", {HeadKind::flat, 2.0, 0.0, 120}, 300, 120}};
}

TEST(ExactHead, MeridiansLieOnTheirClosedForms) {
  std::mt19937 random(7);
  std::vector<Case> all = cases();
  for (const Case& c : conical_cases()) all.push_back(c);
  for (const Case& c : flat_cases()) all.push_back(c);
  for (const Case& c : all) {
    SCOPED_TRACE(c.name);
    const ExactHead h = exact_head(c.preset, c.radius);
    EXPECT_EQ(h.meridian.degree(), 2);
    EXPECT_EQ(h.meridian.size(), 2 * h.arcs + 1);
    const bool knuckled = c.preset.kind == HeadKind::torispherical ||
                          c.preset.kind == HeadKind::flat ||
                          (c.preset.kind == HeadKind::conical && c.preset.knuckle > 0);
    EXPECT_EQ(h.arcs, knuckled ? 4 : 2);
    std::uniform_real_distribution<double> u(h.meridian.front(), h.meridian.back());
    double worst = 0;
    for (int k = 0; k < 20000; ++k)
      worst = std::max(
          worst, std::abs(closed_form_residual(c.preset, c.radius, h.meridian.point(u(random)))));
    EXPECT_LT(worst, 1e-9);
    // The radial error along rays from the origin: rays grazing a shallow flat head's plate
    // (θ ≈ r/R) magnify rounding by 1/sin θ, so there the normal residual above is the measure.
    const double graze = c.preset.kind == HeadKind::flat ? c.radius / c.preset.knuckle : 1.0;
    EXPECT_LT(exact_head_deviation(h.meridian, h.shape, 2000), 1e-9 * graze);
    // Ends, apex and depth.
    EXPECT_NEAR((h.meridian.point(h.meridian.front()) - Eigen::Vector2d(c.radius, 0)).norm(), 0,
                1e-12);
    EXPECT_NEAR((h.meridian.point(h.meridian.back()) - Eigen::Vector2d(-c.radius, 0)).norm(), 0,
                1e-12);
    const Eigen::Vector2d apex = h.meridian.point(h.arcs / 2.0);
    EXPECT_NEAR(apex.x(), 0, 1e-12);
    EXPECT_NEAR(apex.y(), c.depth, 1e-9);
    EXPECT_NEAR(h.shape.depth, c.depth, 1e-9);
  }
}

// The head leaves the cylinder vertically and its arcs meet with one tangent: the joints are
// double knots, so the check is on the one-sided derivatives' directions.
TEST(ExactHead, ArcsMeetTangentially) {
  std::vector<Case> all = cases();
  for (const Case& c : flat_cases()) all.push_back(c);
  for (const Case& c : all) {
    SCOPED_TRACE(c.name);
    const ExactHead h = exact_head(c.preset, c.radius);
    const Eigen::Vector2d start = h.meridian.derivatives(h.meridian.front(), 1)[1];
    EXPECT_NEAR(std::abs(start.normalized().x()), 0, 1e-12);  // vertical at junction A
    for (int joint = 1; joint < h.arcs; ++joint) {
      const double u = joint, e = 1e-7;
      const Eigen::Vector2d before = h.meridian.derivatives(u - e, 1)[1].normalized();
      const Eigen::Vector2d after = h.meridian.derivatives(u + e, 1)[1].normalized();
      EXPECT_NEAR(before.x() * after.y() - before.y() * after.x(), 0, 1e-6) << joint;
      EXPECT_GT(before.dot(after), 0.99);
    }
  }
}

// The cone's meridian runs at α to the axis up to a cone point; its knuckle leaves the cylinder
// vertically and meets the cone with one tangent; without a knuckle the cone meets the cylinder
// at the kink α.
TEST(ExactHead, ConicalHeadsMeetTheirConeAtItsAngle) {
  for (const Case& c : conical_cases()) {
    const double a = c.preset.half_angle;
    SCOPED_TRACE(a * 180 / kPi);
    const ExactHead h = exact_head(c.preset, c.radius);
    const double apex = h.arcs / 2.0, e = 1e-9;
    const Eigen::Vector2d up = h.meridian.derivatives(apex - e, 1)[1].normalized();
    const Eigen::Vector2d down = h.meridian.derivatives(apex + e, 1)[1].normalized();
    EXPECT_NEAR(std::atan2(-up.x(), up.y()), a, 1e-9);       // towards the axis at α
    EXPECT_NEAR(std::atan2(-down.x(), -down.y()), a, 1e-9);  // the mirrored side
    const Eigen::Vector2d start = h.meridian.derivatives(h.meridian.front(), 1)[1].normalized();
    const double kink = c.preset.knuckle > 0 ? 0.0 : a;
    EXPECT_NEAR(std::atan2(-start.x(), start.y()), kink, 1e-9);
    if (c.preset.knuckle > 0) {  // knuckle to cone, tangent
      const Eigen::Vector2d before = h.meridian.derivatives(1 - e, 1)[1].normalized();
      const Eigen::Vector2d after = h.meridian.derivatives(1 + e, 1)[1].normalized();
      EXPECT_NEAR(before.x() * after.y() - before.y() * after.x(), 0, 1e-7);
    }
  }
}

TEST(ExactHead, RevolvesIntoABiquadraticHead) {
  const ExactHead h = exact_head(torispherical_100_6(500), 500);
  const VesselSurfaces s = vessel_surfaces(h.meridian, 1500);
  EXPECT_EQ(s.head.degree_u(), 2);
  EXPECT_EQ(s.head.degree_v(), 2);
  EXPECT_NEAR(s.apex_parameter, h.arcs / 2.0, 1e-12);
}

TEST(ExactHead, BadParametersAreRefused) {
  EXPECT_THROW(exact_head({HeadKind::torispherical, 2.0, 400, 60}, 500), InputError);  // crown < R
  EXPECT_THROW(exact_head({HeadKind::torispherical, 2.0, 1000, 500}, 500), InputError);
  EXPECT_THROW(exact_head({HeadKind::ellipsoidal, 0.0}, 500), InputError);
  EXPECT_THROW(exact_head({}, -1), InputError);
  EXPECT_THROW(exact_head({HeadKind::conical, 2.0, 0.0, 60, 0.0}, 500), InputError);
  EXPECT_THROW(exact_head({HeadKind::conical, 2.0, 0.0, 60, kPi / 2}, 500), InputError);
  EXPECT_THROW(exact_head({HeadKind::conical, 2.0, 0.0, 500, 0.5}, 500), InputError);
  EXPECT_THROW(exact_head({HeadKind::conical, 2.0, 0.0, -1, 0.5}, 500), InputError);
  EXPECT_THROW(exact_head({HeadKind::flat, 2.0, 0.0, 0.0}, 500), InputError);  // no knuckle
  EXPECT_THROW(exact_head({HeadKind::flat, 2.0, 0.0, 500}, 500), InputError);
}

}  // namespace
}  // namespace polarform
