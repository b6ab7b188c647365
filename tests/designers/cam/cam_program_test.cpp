// Cam programs: validation (gap, overlap, coverage, lift, law, closure) with messages naming
// segments and angles; levels, speeds in rpm, the exact piecewise B-spline form, and continuity
// diagnostics with angle and jump size.
#include "designers/cam/cam_program.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/cam/cam_analysis.h"
#include "designers/cam/continuity.h"
#include "src/error.h"
#include "src/units.h"
#include "tests/designers/cam/segment_support.h"

namespace polarform {
namespace {

constexpr double pi = std::numbers::pi;

SegmentSpec segment(std::string name, SegmentKind kind, double from_deg, double to_deg, double lift = 0,
                    MotionLaw law = MotionLaw::Cycloidal) {
  SegmentSpec s = test::segment(kind, from_deg, to_deg, lift, law);
  s.name = std::move(name);
  return s;
}

// dwell 0-90°, rise 10 mm 90-180°, dwell 180-270°, return 270-360°, all with `law`.
std::vector<SegmentSpec> drdr(MotionLaw law) {
  return {segment("dwell 1", SegmentKind::Dwell, 0, 90), segment("rise", SegmentKind::Rise, 90, 180, 10, law),
          segment("dwell 2", SegmentKind::Dwell, 180, 270), segment("return", SegmentKind::Return, 270, 360, 10, law)};
}

std::string error_of(std::vector<SegmentSpec> specs) {
  try {
    CamProgram p(std::move(specs));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CamProgram, ValidationNamesSegmentsAndAngles) {
  auto gap = drdr(MotionLaw::Cycloidal);
  gap[2].start = 185 * kRadiansPerDegree;
  EXPECT_EQ(error_of(gap), "cam program: gap between segment 'rise' (ends at 180°) and segment 'dwell 2' (starts at 185°)");
  auto overlap = drdr(MotionLaw::Cycloidal);
  overlap[1].end = 200 * kRadiansPerDegree;
  EXPECT_EQ(error_of(overlap),
            "cam program: segment 'rise' (90° to 200°) overlaps segment 'dwell 2' (180° to 270°)");
  auto short_end = drdr(MotionLaw::Cycloidal);
  short_end[3].end = 350 * kRadiansPerDegree;
  EXPECT_NE(error_of(short_end).find("the last segment, segment 'return', ends at 350°"), std::string::npos);
  auto late_start = drdr(MotionLaw::Cycloidal);
  late_start[0].start = 10 * kRadiansPerDegree;
  EXPECT_NE(error_of(late_start).find("the first segment, segment 'dwell 1', starts at 10°"), std::string::npos);
  auto negative = drdr(MotionLaw::Cycloidal);
  negative[1].lift = -10;
  EXPECT_NE(error_of(negative).find("segment 'rise': lift must be a positive number of mm for a rise, got -10"),
            std::string::npos)
      << error_of(negative);
  auto unknown = drdr(MotionLaw::Cycloidal);
  unknown[3].law = static_cast<MotionLaw>(42);
  EXPECT_EQ(error_of(unknown), "segment 'return': unknown motion law");
  auto open = drdr(MotionLaw::Cycloidal);
  open[3].lift = 8;
  EXPECT_EQ(error_of(open),
            "cam program: the rises total 10 mm but the returns total 8 mm; the program must end at the level it "
            "starts with");
  auto unnamed = drdr(MotionLaw::Cycloidal);
  unnamed[1].name.clear();
  unnamed[1].end = 170 * kRadiansPerDegree;
  EXPECT_NE(error_of(unnamed).find("segment 'segment 2' (ends at 170°)"), std::string::npos);
  EXPECT_NE(error_of({}).find("no segments"), std::string::npos);
}

TEST(CamProgram, SortsSegmentsAndMeasuresFromTheLowestLevel) {
  auto specs = drdr(MotionLaw::Cycloidal);
  std::swap(specs[0], specs[3]);  // order in the list does not matter
  const CamProgram p(specs);
  EXPECT_EQ(p.segments()[0].name(), "dwell 1");
  EXPECT_EQ(p(45 * kRadiansPerDegree), 0.0);
  EXPECT_EQ(p(200 * kRadiansPerDegree), 10.0);
  EXPECT_NEAR(p(135 * kRadiansPerDegree), 5.0, 1e-14);
  EXPECT_EQ(p.stroke(), 10.0);
  EXPECT_NEAR(p(135 * kRadiansPerDegree + 2 * pi), 5.0, 1e-13);  // periodic
  // Starting with the return: the follower is at the top at θ = 0.
  const CamProgram q({segment("ret", SegmentKind::Return, 0, 180, 6), segment("up", SegmentKind::Rise, 180, 360, 6)});
  EXPECT_EQ(q(0.0), 6.0);
}

// At 60 rpm ω = 2π rad/s: v = s' ω, a = s'' ω², j = s''' ω³.
TEST(CamProgram, KinematicsFromRpm) {
  const CamProgram p(drdr(MotionLaw::Cycloidal));
  const double theta = 120 * kRadiansPerDegree, omega = 2 * pi;
  double s[4];
  p.derivatives(theta, 3, s);
  const Kinematics k = p.kinematics(theta, 60.0);
  EXPECT_EQ(k.displacement, s[0]);
  EXPECT_NEAR(k.velocity, s[1] * omega, 1e-12);
  EXPECT_NEAR(k.acceleration, s[2] * omega * omega, 1e-11);
  EXPECT_NEAR(k.jerk, s[3] * omega * omega * omega, 1e-9);
  // Cycloidal peak velocity: Cv h / β = 2 * 10 / (π/2) mm/rad at mid-rise.
  EXPECT_NEAR(p.kinematics(135 * kRadiansPerDegree, 60.0).velocity, 40 / pi * omega, 1e-12);
  EXPECT_THROW(p.kinematics(0.0, 0.0), InputError);
}

// A harmonic rise next to a dwell: acceleration jumps by h π²/(2 β²) = 10 π²/2 / (π/2)² = 20 mm/rad².
TEST(Continuity, HarmonicNextToDwellReportsAccelerationJumps) {
  const std::vector<ContinuityIssue> issues = check_continuity(CamProgram(drdr(MotionLaw::SimpleHarmonic)));
  ASSERT_EQ(issues.size(), 4u);
  const double expected_angle[4] = {0, 90 * kRadiansPerDegree, 180 * kRadiansPerDegree,
                                    270 * kRadiansPerDegree};
  const double expected_jump[4] = {-20, 20, 20, -20};
  const char* before[4] = {"return", "dwell 1", "rise", "dwell 2"};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(issues[i].derivative, 2);
    EXPECT_EQ(issues[i].before, before[i]);
    EXPECT_NEAR(issues[i].angle, expected_angle[i], 1e-15);
    EXPECT_NEAR(issues[i].jump(), expected_jump[i], 1e-12);
  }
  EXPECT_EQ(issues[1].message(), "acceleration jumps by 20 mm/rad² (0 -> 20) at 90° between 'dwell 1' and 'rise'");
}

// Cycloidal segments are C2 with dwells; only the jerk jumps, by 4π² h / β³ = 4π² 10/(π/2)³ = 320/π.
TEST(Continuity, CycloidalJerkJumpsOnlyWhenJerkIsChecked) {
  const CamProgram p(drdr(MotionLaw::Cycloidal));
  EXPECT_TRUE(check_continuity(p).empty());
  const std::vector<ContinuityIssue> issues = check_continuity(p, 3);
  ASSERT_EQ(issues.size(), 4u);
  for (const ContinuityIssue& i : issues) {
    EXPECT_EQ(i.derivative, 3);
    EXPECT_NEAR(std::abs(i.jump()), 320 / pi, 1e-9);
  }
  EXPECT_TRUE(check_continuity(CamProgram(drdr(MotionLaw::Polynomial4567)), 3).empty());
}

// Polynomial segments join into one B-spline over [0, 2π] of the highest degree with knots of
// multiplicity p at the boundaries; it equals s and its derivatives everywhere.
TEST(CamProgram, ExactBSplineOfAPolynomialProgram) {
  std::vector<SegmentSpec> specs = drdr(MotionLaw::Polynomial345);
  specs[3].law = MotionLaw::BSpline;
  specs[3].bspline = {6, 11, 3};
  const CamProgram p(specs);
  const BSplineFunction f = *p.exact();
  EXPECT_EQ(f.degree(), 6);
  EXPECT_EQ(f.front(), 0.0);
  EXPECT_EQ(f.back(), 2 * pi);
  for (double b : {90 * kRadiansPerDegree, 180 * kRadiansPerDegree, 270 * kRadiansPerDegree})
    EXPECT_EQ(multiplicity(f.knots(), b), 6);
  for (int i = 0; i < 3600; ++i) {  // at 2π the program wraps to θ = 0, the spline ends its last piece
    const double theta = 2 * pi * i / 3600;
    double s[4];
    p.derivatives(theta, 3, s);
    const Eigen::VectorXd e = f.derivatives(theta, 3);
    EXPECT_NEAR(e(0), s[0], 1e-12);
    for (int k = 1; k <= 3; ++k) EXPECT_NEAR(e(k), s[k], 1e-9 * std::max(1.0, std::abs(s[k])));
  }
  EXPECT_FALSE(CamProgram(drdr(MotionLaw::Cycloidal)).exact());
  const CamProgram dwell({segment("dwell", SegmentKind::Dwell, 0, 360)});
  EXPECT_EQ(dwell.exact()->degree(), 0);
}

// Peak velocity of a cycloidal rise is Cv h/β at mid-rise, found between grid points.
TEST(CamProgram, MotionExtremaAreRefinedOffTheGrid) {
  const CamProgram p(drdr(MotionLaw::Cycloidal));
  const std::vector<double> grid = uniform_angles(37);  // 9.73° spacing, misses 135°
  const MotionExtrema m = motion_extrema(p, grid);
  EXPECT_NEAR(m.velocity.value, 2 * 10 / (pi / 2), 1e-9);
  EXPECT_TRUE(std::abs(m.velocity.theta - 135 * kRadiansPerDegree) < 1e-5 ||
              std::abs(m.velocity.theta - 315 * kRadiansPerDegree) < 1e-5)
      << m.velocity.theta * kDegreesPerRadian;
  EXPECT_NEAR(m.acceleration.value, 2 * pi * 10 / std::pow(pi / 2, 2), 1e-9);
  EXPECT_NEAR(m.jerk.value, 4 * pi * pi * 10 / std::pow(pi / 2, 3), 1e-9);
}

}  // namespace
}  // namespace polarform
