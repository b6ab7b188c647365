// Oscillating (swing-arm) roller and flat-faced followers against independent oracles: the arm's
// geometry from plain trigonometry, the roller contour as the envelope (every contact point at
// the roller radius from the roller centres, none closer), the flat face's contact from the
// envelope condition with finite-difference derivatives, pressure angles from finite-difference
// tangents, and the translating follower as the limit of a very long arm.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/cam/cam_analysis.h"
#include "designers/cam/plate_cam.h"
#include "src/error.h"
#include "src/units.h"
#include "tests/designers/cam/cam_test_support.h"
#include "tests/designers/cam/segment_support.h"
#include "tests/support/designers/arm_oracle.h"

namespace polarform {
namespace {

using Eigen::Vector2d;
using test::ArmOracle;
using test::segment;
constexpr double pi = std::numbers::pi;

// Dwell, rise of `lift` over 80°–190° (cycloidal), dwell, return over 250°–360° (4-5-6-7).
CamProgram swing_program(double lift) {
  return CamProgram({segment(SegmentKind::Dwell, 0, 80, 0, MotionLaw::Cycloidal),
                     segment(SegmentKind::Rise, 80, 190, lift, MotionLaw::Cycloidal),
                     segment(SegmentKind::Dwell, 190, 250, 0, MotionLaw::Cycloidal),
                     segment(SegmentKind::Return, 250, 360, lift, MotionLaw::Polynomial4567)});
}

Follower oscillating_roller(double rr, double d, double l, int side) {
  Follower f;
  f.kind = FollowerKind::OscillatingRoller;
  f.roller_radius = rr;
  f.pivot_distance = d;
  f.arm_length = l;
  f.pivot_side = side;
  return f;
}

Follower oscillating_face(double d, double offset, int side) {
  Follower f;
  f.kind = FollowerKind::OscillatingFlatFaced;
  f.pivot_distance = d;
  f.face_offset = offset;
  f.pivot_side = side;
  return f;
}

Vector2d rotate(const Vector2d& v, double angle) { return ArmOracle::rotate(v, angle); }

Vector2d perp(const Vector2d& v) { return {-v.y(), v.x()}; }

double angle_between_lines(const Vector2d& a, const Vector2d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized()))));
}

TEST(OscillatingRoller, PivotArmAndSwingFollowTheDefinition) {
  for (int side : {1, -1}) {
    const PlateCam cam(swing_program(15), oscillating_roller(8, 110, 75, side), 42,
                       Rotation::Clockwise);
    const Vector2d p = cam.pivot();
    EXPECT_NEAR(p.norm(), 110, 1e-12);
    EXPECT_NEAR((p - Vector2d(0, 50)).norm(), 75, 1e-12);
    EXPECT_GT(side * p.x(), 0);
    for (int k = 0; k < 360; ++k) {
      const double theta = k * pi / 180;
      Vector2d q[1];
      cam.pitch(theta, 0, q);
      const Vector2d fixed = rotate(q[0], cam.sense() * theta);  // the roller centre in the world
      EXPECT_NEAR((fixed - p).norm(), 75, 1e-10);
      const double turned = std::atan2(perp(Vector2d(0, 50) - p).dot(fixed - p),
                                       (Vector2d(0, 50) - p).dot(fixed - p));
      EXPECT_NEAR(std::abs(turned) * 180 / pi, cam.program()(theta), 1e-9) << theta;
      if (cam.program()(theta) > 1e-6) {
        EXPECT_GT(fixed.norm(), 50.0);  // the swing moves away from the cam
      }
    }
  }
}

// Every contact point is Rr from its roller centre and no roller position comes closer than Rr to
// it (the contour is the inner envelope of the roller circles).
TEST(OscillatingRoller, ContourIsTheEnvelopeOfTheRollerCircles) {
  for (Rotation rotation : {Rotation::CounterClockwise, Rotation::Clockwise}) {
    const ArmOracle o{swing_program(16), 40, 10, 110, 80, 0, 1, sense(rotation), true};
    const PlateCam cam(o.program, oscillating_roller(10, 110, 80, 1), 40, rotation);
    const int n = 4000;
    std::vector<Vector2d> centres;
    for (int i = 0; i < n; ++i)
      centres.push_back(o.to_cam(o.roller_centre(2 * pi * i / n), 2 * pi * i / n));
    double worst = 0.0;
    for (int i = 0; i < 720; ++i) {
      const double theta = 2 * pi * (i + 0.37) / 720;
      Vector2d c[1];
      cam.contour(theta, 0, c);
      EXPECT_NEAR((c[0] - o.to_cam(o.roller_centre(theta), theta)).norm(), 10, 1e-10);
      // Nearest roller centre by dense sampling, refined by a ternary search on θ.
      const auto distance = [&](double t) {
        return (c[0] - o.to_cam(o.roller_centre(t), t)).norm();
      };
      const test::Maximum m =
          test::dense_maximum([&](double t) { return -distance(t); }, 0, 2 * pi);
      worst = std::max(worst, std::abs(-m.value - 10));
    }
    EXPECT_LT(worst, 1e-8);
  }
}

// The pressure angle: between the contact normal (the pitch curve's normal, from a
// finite-difference tangent) and the roller centre's path, perpendicular to the arm.
TEST(OscillatingRoller, PressureAngleAgainstFiniteDifferenceTangents) {
  for (int side : {1, -1})
    for (Rotation rotation : {Rotation::CounterClockwise, Rotation::Clockwise}) {
      const ArmOracle o{swing_program(16), 40, 10, 110, 80, 0, side, sense(rotation), true};
      const PlateCam cam(o.program, oscillating_roller(10, 110, 80, side), 40, rotation);
      double worst = 0.0;
      for (int i = 0; i < 360; ++i) {
        const double theta = 2 * pi * (i + 0.5) / 360;
        const auto coordinate = [&](int k) {
          return [&, k](double t) { return o.to_cam(o.roller_centre(t), t)[k]; };
        };
        const Vector2d tangent(test::central_difference(coordinate(0), theta, 1e-3),
                               test::central_difference(coordinate(1), theta, 1e-3));
        const Vector2d normal = rotate(perp(tangent), o.sigma * theta);  // into the fixed frame
        const Vector2d path = perp(o.roller_centre(theta) - o.pivot());
        const double expected = pi / 2 - angle_between_lines(normal, perp(path));
        worst = std::max(worst, std::abs(std::abs(cam.pressure_angle(theta)) - expected));
      }
      EXPECT_LT(worst, 1e-9) << side << " " << sense(rotation);
    }
}

// The pressure angle's sign: positive while the follower rises on a cam turning away from the pivot
// at the contact, as for a translating follower whose travel the cam pushes along.
TEST(OscillatingRoller, PressureAngleIsPositiveDuringTheRiseOfATrailingArm) {
  const PlateCam cam(swing_program(16), oscillating_roller(10, 200, 196.5, 1), 40,
                     Rotation::CounterClockwise);
  EXPECT_GT(cam.pressure_angle(135 * pi / 180), 0.1);
  EXPECT_LT(cam.pressure_angle(305 * pi / 180), -0.1);
}

// A very long arm, pivot level with the roller at rest, swings the roller along a nearly straight
// radial path: the cam approaches the radial translating roller follower's as h²/(2L).
TEST(OscillatingRoller, AVeryLongArmApproachesTheTranslatingFollower) {
  const double stroke = 12.0;
  const Follower radial{FollowerKind::Roller, 0.0, 10.0};
  SegmentSpec rise = segment(SegmentKind::Rise, 80, 190, stroke, MotionLaw::Cycloidal);
  SegmentSpec back = segment(SegmentKind::Return, 250, 360, stroke, MotionLaw::Polynomial4567);
  const PlateCam translating(
      CamProgram({segment(SegmentKind::Dwell, 0, 80, 0, MotionLaw::Cycloidal), rise,
                  segment(SegmentKind::Dwell, 190, 250, 0, MotionLaw::Cycloidal), back}),
      radial, 40);
  double previous = 0.0;
  for (double l : {1e4, 1e5}) {
    const double swing =
        std::asin(stroke / l) * 180 / pi;  // the same lift at the top of the stroke
    const PlateCam arm(swing_program(swing), oscillating_roller(10, std::hypot(l, 50.0), l, 1), 40);
    double gap = 0.0, pressure = 0.0;
    for (int i = 0; i < 720; ++i) {
      const double theta = 2 * pi * i / 720;
      Vector2d a[1], b[1];
      arm.contour(theta, 0, a);
      translating.contour(theta, 0, b);
      gap = std::max(gap, (a[0] - b[0]).norm());
      pressure = std::max(pressure,
                          std::abs(arm.pressure_angle(theta) - translating.pressure_angle(theta)));
    }
    EXPECT_LT(gap, 3 * stroke * stroke / l) << l;
    EXPECT_LT(pressure, 30 * stroke / l) << l;
    if (previous > 0) {
      EXPECT_LT(gap, previous / 5);
    }
    previous = gap;
  }
}

// Flat face: its contact from the envelope condition with finite-difference derivatives of the
// face's height h and angle φ relative to the cam (X = h n + (dh/dφ) J n), and, where the analysis
// finds no undercut, the support function (the cam touches each face line and never crosses it).
TEST(OscillatingFlatFace, ContactIsTheEnvelopeOfTheFaceLines) {
  int convex = 0;
  for (double offset : {0.0, 12.0, -9.0})
    for (int side : {1, -1}) {
      const ArmOracle o{swing_program(10), 40, 0, 130, 0, offset, side, 1, false};
      const PlateCam cam(o.program, oscillating_face(130, offset, side), 40);
      const bool undercut = !analyse(cam, uniform_angles(1440)).undercut.empty();
      convex += !undercut;
      double worst = 0.0, worst_support = 0.0;
      std::vector<Vector2d> contour;
      for (int i = 0; i < 20000; ++i) {
        Vector2d c[1];
        cam.contour(2 * pi * i / 20000, 0, c);
        contour.push_back(c[0]);
      }
      for (int i = 0; i < 360; ++i) {
        const double theta = 2 * pi * (i + 0.5) / 360;
        const auto height = [&](double t) { return o.face_height(t); };
        const auto line_angle = [&](double t) {
          const Vector2d n = o.to_cam(o.face_normal(t), t);
          return std::atan2(n.y(), n.x());
        };
        const double lambda = test::central_difference(height, theta, 1e-3) /
                              test::central_difference(line_angle, theta, 1e-3);
        const Vector2d n = o.face_normal(theta);
        const Vector2d expected = o.to_cam(o.face_height(theta) * n + lambda * perp(n), theta);
        Vector2d c[1];
        cam.contour(theta, 0, c);
        worst = std::max(worst, (c[0] - expected).norm());
        // The cam stays on its side of the face (the centre's) and touches it: max of X·n = h.
        const Vector2d nc = o.to_cam(n, theta);
        double support = -1e300;
        for (const Vector2d& x : contour) support = std::max(support, x.dot(nc));
        worst_support = std::max(worst_support, std::abs(support - o.face_height(theta)));
      }
      EXPECT_LT(worst, 1e-8) << offset << " " << side;
      if (!undercut)
        EXPECT_LT(worst_support, 1e-4) << offset << " " << side;  // 20000 samples' sagitta
      else
        EXPECT_GT(worst_support, 1e-3)
            << offset << " " << side;  // an undercut cam crosses the face
    }
  EXPECT_GE(convex, 3);
}

// The contact point travels perpendicular to the line from the pivot; with the face through the
// pivot that is along the face's normal (pressure angle 0), otherwise atan of f over the distance
// along the face.
TEST(OscillatingFlatFace, PressureAngleAndFaceContact) {
  for (double offset : {0.0, 12.0, -9.0}) {
    const ArmOracle o{swing_program(10), 40, 0, 130, 0, offset, 1, 1, false};
    const PlateCam cam(o.program, oscillating_face(130, offset, 1), 40);
    for (int i = 0; i < 72; ++i) {
      const double theta = 2 * pi * (i + 0.5) / 72;
      const CamSample s = cam.sample(theta);
      Vector2d c[1];
      cam.contour(theta, 0, c);
      const Vector2d x = rotate(c[0], theta), n = o.face_normal(theta), p = o.pivot();
      // Along the face from the foot of the pivot's perpendicular, towards the cam centre's side.
      const double along = (x - (p - offset * n)).norm();
      EXPECT_NEAR(s.face_contact, along, 1e-9);
      EXPECT_NEAR(std::abs(s.pressure_angle), std::atan(std::abs(offset) / along), 1e-9);
    }
  }
}

// The contact force's lever about the pivot, against power balance: the work the cam does turning
// by dθ, F·(X × n)·σ dθ (the moment of the force about the cam centre, X the contact point, n the
// push direction), is the work on the arm, F·lever·dq (q the swing in rad).
TEST(OscillatingFollower, ArmLeverBalancesTheCamsPower) {
  for (int side : {1, -1})
    for (Rotation rotation : {Rotation::CounterClockwise, Rotation::Clockwise})
      for (bool roller : {true, false}) {
        const Follower f =
            roller ? oscillating_roller(10, 110, 80, side) : oscillating_face(130, 8, side);
        const PlateCam cam(swing_program(10), f, roller ? 40 : 55, rotation);
        for (int i = 0; i < 72; ++i) {
          const double theta = 2 * pi * (i + 0.5) / 72;
          const CamSample s = cam.sample(theta);
          Vector2d x[1], c[1];
          cam.contour(theta, 0, x);
          cam.pitch(theta, 0, c);
          // The push: from the contact to the roller centre; for a face, along its normal, which is
          // the direction of the face's foot point (the flat follower's pitch point) from the
          // centre.
          const Vector2d push =
              roller ? Vector2d((c[0] - x[0]).normalized()) : Vector2d(c[0].normalized());
          EXPECT_NEAR(s.arm_lever * s.v * pi / 180,
                      sense(rotation) * x[0].x() * push.y() - sense(rotation) * x[0].y() * push.x(),
                      1e-9)
              << side << " " << roller << " " << theta;
          EXPECT_GT(s.arm_lever, 0.0);
        }
      }
}

TEST(OscillatingFollower, GeometryThatCannotWorkIsRefusedNamingTheField) {
  const auto message = [](auto&& make) {
    try {
      make();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // |d − L| = 60 > Rp = 50: the roller never reaches the prime circle.
  EXPECT_NE(message([] {
              PlateCam(swing_program(10), oscillating_roller(10, 140, 80, 1), 40);
            }).find("arm-length"),
            std::string::npos);
  // Rb + f = 130 > d = 120: the face never touches the base circle.
  EXPECT_NE(message([] {
              PlateCam(swing_program(10), oscillating_face(120, 90, 1), 40);
            }).find("pivot-distance"),
            std::string::npos);
  // The roller's reach peaks after the arm turns ~ 90°+: 100° of swing is beyond it.
  const PlateCam ok(swing_program(10), oscillating_roller(10, 110, 80, 1), 40);
  const double limit = ok.max_arm_swing();
  EXPECT_GT(limit, 10);
  EXPECT_NE(message([&] {
              PlateCam(swing_program(limit + 1), oscillating_roller(10, 110, 80, 1), 40);
            }).find("cannot swing the lift"),
            std::string::npos);
  EXPECT_EQ(
      message([&] { PlateCam(swing_program(limit - 1), oscillating_roller(10, 110, 80, 1), 40); }),
      "no error");
}

// The largest swing is where the follower's reach from the cam centre stops growing.
TEST(OscillatingFollower, MaxArmSwingIsWhereTheReachPeaks) {
  for (int side : {1, -1}) {
    const ArmOracle o{swing_program(10), 40, 10, 110, 80, 0, side, 1, true};
    const PlateCam cam(o.program, oscillating_roller(10, 110, 80, side), 40);
    const Vector2d p = o.pivot(), rest = Vector2d(0, 50) - p;
    const test::Maximum reach = test::dense_maximum(
        [&](double deg) { return (p + rotate(rest, -side * deg * pi / 180)).norm(); }, 0, 180);
    EXPECT_NEAR(cam.max_arm_swing(), reach.x, 1e-6);
    EXPECT_NEAR(reach.value, 110 + 80, 1e-9);
  }
}

}  // namespace
}  // namespace polarform
