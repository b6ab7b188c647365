// How a law is laid onto a segment beyond the plain rise: the double harmonic's return is its rise
// played backwards (Rothbart's return formula), so a double-harmonic rise straight into a
// double-harmonic return is C² at the top; a rise–return is one segment that comes back to its
// start level (the 3-4-5-6 polynomial of Norton's single-dwell example, peak factors derived by
// hand); and constant velocity without blends is refused between dwells.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/cam/cam_program.h"
#include "designers/cam/continuity.h"
#include "src/error.h"
#include "tests/designers/cam/cam_test_support.h"
#include "tests/designers/cam/segment_support.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

using test::segment;

double at(const MotionSegment& s, double x, int k) {
  double out[5];
  s.derivatives(s.start() + x * (s.end() - s.start()), 4, out);
  return out[k];
}

// Rothbart, Cams (1956), double harmonic return: s = h/2 [(1 + cos πx) − ¼(1 − cos 2πx)].
TEST(SegmentShapes, DoubleHarmonicReturnIsRothbartsReturn) {
  const double h = 12;
  const MotionSegment ret(segment(SegmentKind::Return, 0, 90, h, MotionLaw::DoubleHarmonic), h);
  for (int i = 0; i <= 100; ++i) {
    const double x = i / 100.0;
    EXPECT_NEAR(at(ret, x, 0),
                h / 2 * ((1 + std::cos(kPi * x)) - 0.25 * (1 - std::cos(2 * kPi * x))), 1e-13);
  }
  const double beta = kPi / 2;  // the return starts decelerating at −π²h/β², ends at rest
  EXPECT_NEAR(at(ret, 0, 2), -kPi * kPi * h / (beta * beta), 1e-12);
  EXPECT_NEAR(at(ret, 1, 2), 0, 1e-12);
  EXPECT_NEAR(at(ret, 1, 0), 0, 1e-14);
}

TEST(SegmentShapes, DoubleHarmonicRiseIntoReturnIsSmoothToAcceleration) {
  const CamProgram p({segment(SegmentKind::Dwell, 0, 90, 0, MotionLaw::Cycloidal),
                      segment(SegmentKind::Rise, 90, 180, 10, MotionLaw::DoubleHarmonic),
                      segment(SegmentKind::Return, 180, 270, 10, MotionLaw::DoubleHarmonic),
                      segment(SegmentKind::Dwell, 270, 360, 0, MotionLaw::Cycloidal)});
  for (const ContinuityIssue& issue : check_continuity(p, 2)) ADD_FAILURE() << issue.message();
  double top[3];
  p.derivatives(kPi, 2, top);
  EXPECT_NEAR(top[2], -kPi * kPi * 10 / (kPi / 2 * kPi / 2), 1e-12);  // −π²h/β² on both sides
}

// 64x³(1 − x)³: S' = 192x²(1 − x)²(1 − 2x) peaks at x = ½ − √5/10 with 192√5/125; S'' peaks at the
// top (−24); S''' = 384 at the ends (derived by hand).
TEST(SegmentShapes, PolynomialRiseReturnIsNortons3456) {
  const double h = 1;
  const MotionSegment s(segment(SegmentKind::RiseReturn, 0, 180 / kPi, h, MotionLaw::Polynomial),
                        0);  // β = 1 rad
  EXPECT_EQ(s.end_level(), 0.0);
  ASSERT_TRUE(s.exact());
  EXPECT_EQ(s.exact()->degree(), 6);
  for (double x : {0.1, 0.3, 0.5, 0.8})
    EXPECT_NEAR(at(s, x, 0), 64 * std::pow(x * (1 - x), 3), 1e-14);
  const test::PeakFactors p = test::peak_factors([&](double x, int k) { return at(s, x, k); });
  EXPECT_NEAR(p.cv, 192 * std::sqrt(5.0) / 125, 1e-9);
  EXPECT_NEAR(p.ca, 24, 1e-9 * 24);
  EXPECT_NEAR(p.cj, 384, 1e-9 * 384);
  for (double x : {0.0, 1.0})
    for (int k = 0; k <= 2; ++k) EXPECT_NEAR(at(s, x, k), 0, 1e-12);
}

// Any closed-form law rises over the first half and returns over the second: top at ½, C² there,
// velocity and acceleration of the law doubled and quadrupled.
TEST(SegmentShapes, RiseReturnWithALawFoldsItAtTheTop) {
  const MotionSegment s(
      segment(SegmentKind::RiseReturn, 0, 180 / kPi, 5, MotionLaw::DoubleHarmonic), 2);
  EXPECT_NEAR(at(s, 0.5, 0), 7, 1e-14);
  for (int k = 0; k <= 2; ++k) EXPECT_NEAR(at(s, 0.5 - 1e-12, k), at(s, 0.5 + 1e-12, k), 1e-8) << k;
  EXPECT_NEAR(at(s, 0.5, 2), 5 * 4 * -kPi * kPi, 1e-10);
  EXPECT_NEAR(test::peak_factors([&](double x, int k) { return at(s, x, k); }).cv,
              5 * 2 * 3 * std::sqrt(3.0) * kPi / 8, 1e-9);
  EXPECT_EQ(s.joins(), std::vector<double>{0.5});
  EXPECT_FALSE(s.exact());
  const MotionSegment sine(segment(SegmentKind::RiseReturn, 0, 90, 5, MotionLaw::ModifiedSine), 0);
  EXPECT_EQ(sine.joins().size(), 5u);  // the top and each half's two joins
  EXPECT_THROW(MotionSegment(segment(SegmentKind::RiseReturn, 0, 90, 5, MotionLaw::BSpline), 0),
               InputError);
}

TEST(SegmentShapes, ARiseReturnPeaksInsideTheProgram) {
  const CamProgram p({segment(SegmentKind::Dwell, 0, 180, 0, MotionLaw::Cycloidal),
                      segment(SegmentKind::RiseReturn, 180, 360, 15, MotionLaw::Polynomial)});
  EXPECT_EQ(p.stroke(), 15.0);
  EXPECT_NEAR(p(1.5 * kPi), 15, 1e-12);
  EXPECT_TRUE(check_continuity(p, 2).empty());
}

TEST(SegmentShapes, UnblendedConstantVelocityNeedsNeighboursAtItsVelocity) {
  SegmentSpec cv = segment(SegmentKind::Rise, 120, 240, 12, MotionLaw::ConstantVelocity);
  cv.blend = 0;
  const double v = 12 / (2 * kPi / 3);  // mm/rad
  try {
    CamProgram({segment(SegmentKind::Dwell, 0, 120, 0, MotionLaw::Cycloidal), cv,
                segment(SegmentKind::Return, 240, 360, 12, MotionLaw::Cycloidal)});
    ADD_FAILURE() << "accepted a velocity step";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("without blends (blend=\"0\")"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("infinite acceleration"), std::string::npos) << e.what();
  }
  // Polynomial ramps that reach and leave v: accepted, velocity continuous.
  SegmentSpec up = segment(SegmentKind::Rise, 0, 120, 6, MotionLaw::Polynomial);
  up.constrained_order = 2;
  up.at_end.velocity = v;
  SegmentSpec down = segment(SegmentKind::Return, 240, 360, 18, MotionLaw::Polynomial);
  down.constrained_order = 2;
  down.at_start.velocity = v;
  const CamProgram p({up, cv, down});
  for (const ContinuityIssue& issue : check_continuity(p, 1)) ADD_FAILURE() << issue.message();
  double mid[3];
  p.derivatives(kPi, 2, mid);
  EXPECT_NEAR(mid[1], v, 1e-12);
  EXPECT_EQ(mid[2], 0.0);
}

}  // namespace
}  // namespace polarform
