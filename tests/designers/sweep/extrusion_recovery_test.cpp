// Extrusion recovery (spec K10, issue 18): an ellipse (semi-axes 20 and 10), a rounded rectangle
// and a C shape (not star-shaped) extruded along a tilted direction, and a plate-cam wall
// (designers/cam) along z, sampled on their sides. The direction from the normals (errors 1.2e-4
// / 5.4e-5 rad noise-free, 4.1e-5 at σ = 0.01, 2.0e-4 on the cam) is refined against the section:
// measured 5.5e-7 / 3.3e-7 rad noise-free (the section fitted to 5e-3), 6.2e-6 (σ = 0.01, long
// ellipse), 2.4e-5 (cam; the issue asks 1e-4); rms ≤ 1.2σ and truth-to-fit rms ≤ σ.
#include "designers/sweep/extrusion_recovery.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "designers/cam/plate_cam.h"
#include "src/nurbs/point_inversion.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

// A closed section: point and unit outward normal at t in [0, 1).
using Section = std::function<std::pair<Eigen::Vector2d, Eigen::Vector2d>(double)>;

Section ellipse(double a, double b) {
  return [=](double t) {
    const double s = 2 * kPi * t;
    const Eigen::Vector2d n(b * std::cos(s), a * std::sin(s));
    return std::pair{Eigen::Vector2d(a * std::cos(s), b * std::sin(s)), n.normalized()};
  };
}

// A 40×24 rectangle with corner radius 5, by arc length.
Section rounded_rectangle() {
  return [](double t) {
    const double hx = 15, hy = 7, r = 5, q = kPi * r / 2;
    const double L = 4 * hx + 4 * hy + 4 * q;
    double s = t * L;
    const double runs[4] = {2 * hy, 2 * hx, 2 * hy, 2 * hx};
    const Eigen::Vector2d centre[4] = {{hx, -hy}, {hx, hy}, {-hx, hy}, {-hx, -hy}};
    for (int side = 0; side < 4; ++side) {
      const double a0 = side * kPi / 2;  // the outward normal direction of this straight side
      const Eigen::Vector2d n(std::cos(a0), std::sin(a0)), along(-n.y(), n.x());
      if (s <= runs[side]) return std::pair{Eigen::Vector2d(centre[side] + r * n + s * along), n};
      s -= runs[side];
      if (s <= q || side == 3) {
        const double a = a0 + std::min(s, q) / r;
        const Eigen::Vector2d m(std::cos(a), std::sin(a));
        return std::pair{Eigen::Vector2d(centre[(side + 1) % 4] + r * m), m};
      }
      s -= q;
    }
    return std::pair{Eigen::Vector2d(hx + r, -hy), Eigen::Vector2d(1, 0)};
  };
}

// A C-shaped section, not star-shaped about any point near its centroid: the outer arc of radius
// 20 from −135° to 135°, a straight cap, the inner arc of radius 12 back, a cap; by arc length.
Section c_shape() {
  return [](double t) {
    const double ro = 20, ri = 12, a0 = -0.75 * kPi, a1 = 0.75 * kPi, cap = ro - ri;
    const double outer = ro * (a1 - a0), inner = ri * (a1 - a0);
    double s = t * (outer + inner + 2 * cap);
    const auto radial = [](double a) { return Eigen::Vector2d(std::cos(a), std::sin(a)); };
    const auto tangent = [](double a) { return Eigen::Vector2d(-std::sin(a), std::cos(a)); };
    if (s <= outer) {
      const double a = a0 + s / ro;
      return std::pair{Eigen::Vector2d(ro * radial(a)), radial(a)};
    }
    s -= outer;
    if (s <= cap) return std::pair{Eigen::Vector2d((ro - s) * radial(a1)), tangent(a1)};
    s -= cap;
    if (s <= inner) {
      const double a = a1 - s / ri;
      return std::pair{Eigen::Vector2d(ri * radial(a)), Eigen::Vector2d(-radial(a))};
    }
    s -= inner;
    return std::pair{Eigen::Vector2d((ri + std::min(s, cap)) * radial(a0)),
                     Eigen::Vector2d(-tangent(a0))};
  };
}

struct Sampled {
  Eigen::Matrix3Xd points, truth;  // noisy and on the surface
  Eigen::Vector3d direction;
  double length;
};

// n random points on the side of the section extruded over [0, length] along a tilted direction.
Sampled sample(const Section& section, double length, int n, double sigma, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  std::normal_distribution<double> N(0, 1);
  const Eigen::Matrix3d R = (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 0.5).normalized()) *
                             Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitZ()))
                                .toRotationMatrix();
  const Eigen::Vector3d shift(12, -7, 31);
  Sampled s{Eigen::Matrix3Xd(3, n), Eigen::Matrix3Xd(3, n), R.col(2), length};
  for (int k = 0; k < n; ++k) {
    const auto [p, m] = section(U(rng));
    const Eigen::Vector3d on = R * Eigen::Vector3d(p.x(), p.y(), length * U(rng)) + shift;
    s.truth.col(k) = on;
    s.points.col(k) = on + sigma * N(rng) * (R * Eigen::Vector3d(m.x(), m.y(), 0));
  }
  return s;
}

double angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), std::abs(a.dot(b)));
}

void expect_exact(const Section& section, const char* name) {
  SCOPED_TRACE(name);
  const Sampled s = sample(section, 60, 20000, 0.0, 7);
  ExtrusionOptions o;
  o.tolerance = 5e-3;
  const ExtrusionRecovery r = recover_extrusion(s.points, o);
  const double err = angle(r.direction, s.direction);
  std::printf("%s: direction error %.3g rad, max %.3g mm\n", name, err, r.error.max);
  EXPECT_LE(err, 2e-6);
  EXPECT_LT(angle(r.start_direction, s.direction), 1e-3);  // the normals' start
  EXPECT_LT(r.normals_flatness, 1e-3);
  ASSERT_EQ(r.surfaces.size(), 1u);
  EXPECT_TRUE(r.profile.loops[0].closed);
  EXPECT_EQ(r.surfaces[0].degree_v(), 1);
  EXPECT_EQ(r.surfaces[0].degree_u(), r.profile.loops[0].curve.degree());
  EXPECT_NEAR(r.length(), 60, 1e-2);
  EXPECT_LE(r.error.max, o.tolerance);
  // Independent check of the reported distances: surface point inversion on a sample.
  for (Eigen::Index k = 0; k < s.points.cols(); k += 97)
    EXPECT_LE(closest_point(r.surfaces[0], s.points.col(k)).distance, 1.0001 * o.tolerance);
}

TEST(ExtrusionRecovery, TiltedEllipseNoiseFree) { expect_exact(ellipse(20, 10), "ellipse"); }

TEST(ExtrusionRecovery, TiltedRoundedRectangleNoiseFree) {
  expect_exact(rounded_rectangle(), "rounded rectangle");
}

// Not star-shaped: the polar fit refuses it and the MLS-thinned band gives the loop, its four
// corners kept.
TEST(ExtrusionRecovery, TiltedCShapeNoiseFree) { expect_exact(c_shape(), "C shape"); }

TEST(ExtrusionRecovery, TiltedEllipseWithNoise) {
  const double sigma = 0.01;
  const Sampled s = sample(ellipse(20, 10), 120, 40000, sigma, 11);
  ExtrusionOptions o;
  o.tolerance = 4 * sigma;
  const ExtrusionRecovery r = recover_extrusion(s.points, o);
  const double err = angle(r.direction, s.direction);
  double sq = 0;
  for (Eigen::Index k = 0; k < s.truth.cols(); k += 20)
    sq += std::pow(closest_point(r.surfaces.at(0), s.truth.col(k)).distance, 2);
  const double truth_rms = std::sqrt(sq / (s.truth.cols() / 20));
  std::printf("noisy ellipse: direction error %.3g rad, rms %.4g, truth rms %.4g\n", err,
              r.error.rms, truth_rms);
  EXPECT_LE(err, 3e-5);
  // The reported uncertainty (direction_sd_deg in report.json) covers the error actually made.
  const double sd = std::sqrt(r.refinement.covariance.trace());
  std::printf("noisy ellipse: direction sd %.3g rad\n", sd);
  EXPECT_GT(sd, 0.0);
  EXPECT_LE(err, 5 * sd);
  EXPECT_LE(r.error.rms, 1.2 * sigma);
  EXPECT_LE(truth_rms, sigma);
  EXPECT_NEAR(r.length(), 120, 6 * sigma);
}

// The wall of a roller plate cam (cycloidal rise 20 mm, dwell, return, dwell; base radius 40,
// roller 10), 15 mm thick along z, 30000 points with σ = 0.01 along the wall's normal.
TEST(ExtrusionRecovery, PlateCamWallWithNoise) {
  std::vector<SegmentSpec> segments;
  const SegmentKind kinds[4] = {SegmentKind::Rise, SegmentKind::Dwell, SegmentKind::Return,
                                SegmentKind::Dwell};
  for (int i = 0; i < 4; ++i) {
    SegmentSpec s;
    s.kind = kinds[i];
    s.start = i * kPi / 2;
    s.end = (i + 1) * kPi / 2;
    s.lift = i % 2 == 0 ? 20 : 0;
    s.law = MotionLaw::Cycloidal;
    segments.push_back(s);
  }
  const CamProgram program(segments);
  const PlateCam cam(program, {FollowerKind::Roller, 0.0, 10.0}, 40.0);
  const double sigma = 0.01, thickness = 15;
  const int n = 30000;
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> U(0, 1);
  std::normal_distribution<double> N(0, 1);
  Eigen::Matrix3Xd P(3, n), truth(3, n);
  for (int k = 0; k < n; ++k) {
    Eigen::Vector2d c[2];
    cam.contour(2 * kPi * U(rng), 1, c);
    const Eigen::Vector2d m = Eigen::Vector2d(c[1].y(), -c[1].x()).normalized();
    truth.col(k) = Eigen::Vector3d(c[0].x(), c[0].y(), thickness * U(rng));
    P.col(k) = truth.col(k) + sigma * N(rng) * Eigen::Vector3d(m.x(), m.y(), 0);
  }
  ExtrusionOptions o;
  o.tolerance = 4.5 * sigma;
  const ExtrusionRecovery r = recover_extrusion(P, o);
  const double err = angle(r.direction, Eigen::Vector3d::UnitZ());
  ASSERT_EQ(r.surfaces.size(), 1u);
  EXPECT_TRUE(r.profile.loops[0].closed);
  double sq = 0;
  for (Eigen::Index k = 0; k < n; k += 20)
    sq += std::pow(closest_point(r.surfaces[0], truth.col(k)).distance, 2);
  const double truth_rms = std::sqrt(sq / (n / 20));
  std::printf("plate cam: direction error %.3g rad, rms %.4g, truth rms %.4g, length %.6g\n", err,
              r.error.rms, truth_rms, r.length());
  EXPECT_LE(err, 1e-4);
  EXPECT_LE(r.error.rms, 1.2 * sigma);
  EXPECT_LE(truth_rms, sigma);
  EXPECT_NEAR(r.length(), thickness, 6 * sigma);
}

}  // namespace
}  // namespace polarform
