// Plate cam geometry and analyses against closed forms: a flat-faced follower on harmonic motion
// is an eccentric circle; a hand-checked roller case; the contour's PolarFunction against the
// parametric contour and finite differences; undercut detection; the minimum base radius.
#include "designers/cam/plate_cam.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "designers/cam/base_radius.h"
#include "designers/cam/cam_analysis.h"
#include "designers/cam/contour_polar_function.h"
#include "src/error.h"
#include "src/units.h"
#include "tests/designers/cam/cam_test_support.h"
#include "tests/designers/cam/segment_support.h"
#include "tests/support/designers/example_cams.h"
#include "tests/support/designers/random_cams.h"

namespace polarform {
namespace {

constexpr double pi = std::numbers::pi;

using test::segment;

// Harmonic rise and return of 2d over 180° each: s = d (1 - cos θ).
CamProgram eccentric_program(double d) {
  return CamProgram({segment(SegmentKind::Rise, 0, 180, 2 * d, MotionLaw::SimpleHarmonic),
                     segment(SegmentKind::Return, 180, 360, 2 * d, MotionLaw::SimpleHarmonic)});
}

// Cycloidal rise 20 mm over 0-90°, dwell, cycloidal return over 180-270°, dwell.
CamProgram rdrd_program() {
  return CamProgram({segment(SegmentKind::Rise, 0, 90, 20, MotionLaw::Cycloidal),
                     segment(SegmentKind::Dwell, 90, 180, 0, MotionLaw::Cycloidal),
                     segment(SegmentKind::Return, 180, 270, 20, MotionLaw::Cycloidal),
                     segment(SegmentKind::Dwell, 270, 360, 0, MotionLaw::Cycloidal)});
}

// R(ψ) and derivatives from the PolarFunction.
double polar(const PolarFunction& f, double psi, int k) {
  double out[4];
  f.derivatives(psi, 3, out);
  return out[k];
}

// ψ of a cam-frame point, unwrapped into the function's domain.
double domain_angle(const PolarFunction& f, const Eigen::Vector2d& p) {
  const double psi = std::atan2(p.y(), p.x());
  return psi - 2 * pi * std::floor((psi - f.start) / (2 * pi));
}

// R(ψ) alone (first order from the Hermite start of θ(ψ)) agrees with R from the Newton-inverted
// θ (the derivatives' path) to round-off: on the plate examples, 20 random designs (translating
// followers) and swing-arm roller and flat-faced followers on either side.
TEST(PlateCam, RAloneAgreesWithTheNewtonInversion) {
  std::vector<PlateCam> cams;
  for (const std::string& name : test::example_cam_names())
    if (name != "cylindrical") cams.push_back(make_plate_cam(test::example_cam_design(name)));
  std::mt19937 rng(20261206);
  for (int k = 0; k < 20; ++k) cams.push_back(make_plate_cam(test::random_cam_design(rng)));
  const CamProgram swing({segment(SegmentKind::Dwell, 0, 80, 0, MotionLaw::Cycloidal),
                          segment(SegmentKind::Rise, 80, 190, 10, MotionLaw::Cycloidal),
                          segment(SegmentKind::Dwell, 190, 250, 0, MotionLaw::Cycloidal),
                          segment(SegmentKind::Return, 250, 360, 10, MotionLaw::Polynomial4567)});
  for (int side : {1, -1}) {
    Follower roller;
    roller.kind = FollowerKind::OscillatingRoller;
    roller.roller_radius = 8, roller.pivot_distance = 110, roller.arm_length = 75;
    roller.pivot_side = side;
    cams.emplace_back(swing, roller, 42, Rotation::Clockwise);
    Follower face;
    face.kind = FollowerKind::OscillatingFlatFaced;
    face.pivot_distance = 130, face.face_offset = 0, face.pivot_side = side;
    cams.emplace_back(swing, face, 60);
  }
  for (std::size_t c = 0; c < cams.size(); ++c) {
    const PolarFunction f = cam_polar_function(cams[c]);
    double worst = 0.0;
    for (int i = 0; i < 4000; ++i) {
      const double psi = f.start + (f.end - f.start) * (i + 0.31) / 4000;
      worst = std::max(worst, std::abs(f(psi) - polar(f, psi, 0)));
    }
    EXPECT_LT(worst, 2e-12) << "cam " << c;
  }
}

// A flat-faced follower with s = d(1 - cos θ) is driven by a circle of radius Rc = Rb + d whose
// centre sits at distance d from the cam centre (on the -y side at θ = 0): ρ = Rb + s + s'' = Rc,
// pressure angle 0, and R(ψ) = -d sin ψ + sqrt(Rc² - d² cos² ψ).
TEST(PlateCam, FlatFacedHarmonicCamIsAnEccentricCircle) {
  const double d = 5, rb = 25, rc = 30;
  for (Rotation rot : {Rotation::CounterClockwise, Rotation::Clockwise}) {
    const PlateCam cam(eccentric_program(d), {FollowerKind::FlatFaced, 3.0, 0.0}, rb, rot);
    const PolarFunction f = cam_polar_function(cam);
    EXPECT_TRUE(f.closed());
    EXPECT_FALSE(f.exact);
    for (int i = 0; i < 720; ++i) {
      const double theta = 2 * pi * i / 720;
      Eigen::Vector2d c[1];
      cam.contour(theta, 0, c);
      EXPECT_NEAR((c[0] - Eigen::Vector2d(0, -d)).norm(), rc, 1e-12);
      const CamSample smp = cam.sample(theta);
      EXPECT_NEAR(cam.contour_radius_of_curvature(theta), rc, 1e-10);
      EXPECT_NEAR(smp.contour_speed, rc, 1e-12);
      EXPECT_EQ(smp.pressure_angle, 0.0);
      const double psi = domain_angle(f, c[0]);
      const double closed = -d * std::sin(psi) + std::sqrt(rc * rc - d * d * std::cos(psi) * std::cos(psi));
      EXPECT_NEAR(f(psi), closed, 1e-12);
      // DESIGN §4.4 curvature of the polar function: 1/Rc.
      const double R = polar(f, psi, 0), R1 = polar(f, psi, 1), R2 = polar(f, psi, 2);
      EXPECT_NEAR((R * R + 2 * R1 * R1 - R * R2) / std::pow(R * R + R1 * R1, 1.5), 1 / rc, 1e-11);
    }
    // Face width: the contact runs over σ s' - e = ±d - e.
    const CamAnalysis a = analyse(cam, uniform_angles(90));
    ASSERT_TRUE(a.face_width);
    EXPECT_NEAR(a.face_width->left, -d - 3.0, 1e-10);
    EXPECT_NEAR(a.face_width->right, d - 3.0, 1e-10);
    EXPECT_NEAR(a.min_convex_contour_radius.value, rc, 1e-9);
    EXPECT_TRUE(a.undercut.empty());
  }
}

// Hand check, radial roller: Rb = 40, Rr = 10 (prime radius 50), cycloidal rise h = 20 over
// β = 90°. At θ = 45°: s = h/2 = 10, s' = 2h/β = 80/π = 25.46479 mm/rad, s'' = 0.
//   pressure angle φ = atan(s'/(Rp + s)) = atan(25.46479/60) = 0.401374 rad = 22.997°;
//   pitch radius of curvature (polar curve R = 60, R' = s', R'' = 0, DESIGN §4.4)
//   ρ = (R² + R'²)^{3/2} / (R² + 2R'²) = 4248.46^{1.5} / 4896.91 = 56.5489 mm; contour ρ = 46.5489 mm.
// Offset e = 8 mm, counter-clockwise: y0 = sqrt(50² - 8²) = 49.3559,
//   φ = atan((s' - e)/(y0 + s)) = atan(17.46479/59.3559) = 0.286163 rad = 16.396°.
TEST(PlateCam, RollerPressureAngleAndCurvatureHandCheck) {
  const PlateCam radial(rdrd_program(), {FollowerKind::Roller, 0.0, 10.0}, 40.0);
  EXPECT_NEAR(radial.pressure_angle(45 * kRadiansPerDegree), 0.4013735019791403, 1e-13);
  EXPECT_NEAR(radial.pitch_radius_of_curvature(45 * kRadiansPerDegree), 56.548930778552865, 1e-10);
  EXPECT_NEAR(radial.contour_radius_of_curvature(45 * kRadiansPerDegree), 46.548930778552865,
              1e-10);
  const PlateCam offset(rdrd_program(), {FollowerKind::Roller, 8.0, 10.0}, 40.0);
  EXPECT_NEAR(offset.pressure_angle(45 * kRadiansPerDegree), 0.2861628924534735, 1e-13);
  // On a dwell the pitch curve is a circle through (e, y0 + s): radius sqrt(e² + (y0 + s)²) =
  // sqrt(64 + 69.35585²) = 69.81571 at the top dwell (s = 20), Rp = 50 at the bottom one; the
  // contour's radius is Rr less.
  const double top = std::hypot(8.0, std::sqrt(50.0 * 50.0 - 64.0) + 20.0);
  EXPECT_NEAR(top, 69.81571, 1e-5);
  EXPECT_NEAR(offset.pitch_radius_of_curvature(135 * kRadiansPerDegree), top, 1e-10);
  EXPECT_NEAR(offset.contour_radius_of_curvature(135 * kRadiansPerDegree), top - 10.0, 1e-10);
  EXPECT_NEAR(offset.contour_radius_of_curvature(300 * kRadiansPerDegree), 40.0, 1e-10);
}

// The contour PolarFunction reproduces the parametric contour to 1e-12 and its derivatives agree
// with finite differences; the pitch curve's polar curvature (§4.4) equals the Cartesian one.
TEST(PlateCam, ContourPolarFunctionReproducesTheContour) {
  for (Rotation rot : {Rotation::CounterClockwise, Rotation::Clockwise}) {
    for (const Follower& follower : {Follower{FollowerKind::Roller, 8.0, 10.0}, Follower{FollowerKind::KnifeEdge, -6.0, 0.0},
                                     Follower{FollowerKind::FlatFaced, 0.0, 0.0}}) {
      const PlateCam cam(rdrd_program(), follower, 40.0, rot);
      const PolarFunction f = cam_polar_function(cam);
      EXPECT_NEAR(f.end - f.start, 2 * pi, 1e-14);
      ASSERT_EQ(f.breakpoints.size(), 3u);
      for (int i = 0; i < 360; ++i) {
        const double theta = 2 * pi * (i + 0.37) / 360;
        Eigen::Vector2d c[1];
        cam.contour(theta, 0, c);
        const double psi = domain_angle(f, c[0]);
        const Eigen::Vector2d back = f(psi) * Eigen::Vector2d(std::cos(psi), std::sin(psi));
        EXPECT_LT((back - c[0]).norm(), 1e-12) << "θ = " << theta;
        // Up to the second derivative R comes from one curve point taken back to ψ along its
        // Taylor series, the third from Newton's θ at ψ: the same values.
        double newton[4];
        f.derivatives(psi, 3, newton);
        for (int d = 0; d <= 2; ++d) {
          double first_order[3];
          f.derivatives(psi, d, first_order);
          for (int k = 0; k <= d; ++k)
            EXPECT_NEAR(first_order[k], newton[k], 1e-12 * std::max(1.0, std::abs(newton[k])))
                << "derivative " << k << " of " << d << " θ = " << theta;
        }
        bool near_break = false;
        for (double b : f.breakpoints) near_break |= std::abs(psi - b) < 0.02;
        if (near_break) continue;
        for (int k = 1; k <= 3; ++k) {
          // The flat face's contour is nearly cusped at the top of the rise (ρ = Rb + s + s''
          // dips to ~9 mm), so R''' varies fast: a small step keeps the difference accurate.
          const double fd = test::central_difference([&](double x) { return polar(f, x, k - 1); }, psi, 2e-4);
          EXPECT_NEAR(polar(f, psi, k), fd, 1e-6 * std::max(1.0, std::abs(fd))) << "derivative " << k << " θ = " << theta;
        }
      }
      const PolarFunction pitch = cam_polar_function(cam, CamCurve::Pitch);
      for (int i = 0; i < 36; ++i) {
        const double theta = 2 * pi * (i + 0.5) / 36;
        Eigen::Vector2d p[1];
        cam.pitch(theta, 0, p);
        const double psi = domain_angle(pitch, p[0]);
        const double R = polar(pitch, psi, 0), R1 = polar(pitch, psi, 1), R2 = polar(pitch, psi, 2);
        const double kappa = (R * R + 2 * R1 * R1 - R * R2) / std::pow(R * R + R1 * R1, 1.5);
        EXPECT_NEAR(kappa, cam.sample(theta).pitch_curvature, 1e-10);
      }
    }
  }
}

// Radial knife-edge: R(ψ) = Rb + s(θ(ψ)) with ψ = π/2 - σθ; a polynomial program gives an exact
// B-spline that equals R and its derivatives.
TEST(PlateCam, RadialKnifeEdgeContourIsExact) {
  const CamProgram program({segment(SegmentKind::Rise, 0, 120, 15, MotionLaw::Polynomial345),
                            segment(SegmentKind::Dwell, 120, 200, 0, MotionLaw::Cycloidal),
                            segment(SegmentKind::Return, 200, 360, 15, MotionLaw::Polynomial4567)});
  for (Rotation rot : {Rotation::CounterClockwise, Rotation::Clockwise}) {
    const PlateCam cam(program, {FollowerKind::KnifeEdge, 0.0, 0.0}, 30.0, rot);
    const PolarFunction f = cam_polar_function(cam);
    ASSERT_TRUE(f.exact);
    EXPECT_EQ(f.exact->degree(), 7);
    EXPECT_NEAR(f.exact->front(), f.start, 1e-15);
    EXPECT_NEAR(f.exact->back(), f.end, 1e-15);
    for (int i = 0; i <= 1000; ++i) {
      const double psi = f.start + (f.end - f.start) * i / 1000;
      const Eigen::VectorXd e = f.exact->derivatives(psi, 3);
      EXPECT_NEAR(f(psi), e(0), 1e-12);
      // The 3-4-5 jerk jumps at the segment ends, where either side may be reported.
      const bool at_break = i == 0 || i == 1000 ||
                            std::any_of(f.breakpoints.begin(), f.breakpoints.end(),
                                        [&](double b) { return std::abs(b - psi) < 1e-9; });
      for (int k = 1; k <= (at_break ? 2 : 3); ++k)
        EXPECT_NEAR(polar(f, psi, k), e(k), 1e-9 * std::max(1.0, std::abs(e(k))));
      const double theta = cam_angle(psi, rot);
      Eigen::Vector2d c[1];
      cam.contour(theta, 0, c);
      EXPECT_LT((f(psi) * Eigen::Vector2d(std::cos(psi), std::sin(psi)) - c[0]).norm(), 1e-12);
    }
  }
}

// A large roller on a steep rise: the pitch curve's convex radius drops below Rr near the top.
TEST(PlateCam, UndercutIsReportedWithItsAngles) {
  const CamProgram steep({segment(SegmentKind::Rise, 0, 40, 25, MotionLaw::Cycloidal),
                          segment(SegmentKind::Dwell, 40, 180, 0, MotionLaw::Cycloidal),
                          segment(SegmentKind::Return, 180, 220, 25, MotionLaw::Cycloidal),
                          segment(SegmentKind::Dwell, 220, 360, 0, MotionLaw::Cycloidal)});
  const PlateCam cam(steep, {FollowerKind::Roller, 0.0, 25.0}, 20.0);
  const CamAnalysis a = analyse(cam, uniform_angles(720));
  ASSERT_FALSE(a.undercut.empty());
  EXPECT_LT(a.min_contour_speed.value, 0.0);
  for (const AngleRange& r : a.undercut) {
    EXPECT_LT(r.from, r.to);
    // The ends are where 1 - Rr κ_pitch changes sign.
    for (double t : {r.from, r.to}) EXPECT_NEAR(cam.sample(t).contour_speed, 0.0, 1e-6);
  }
  try {
    cam_polar_function(cam);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not single-valued in polar angle between θ = "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("reduce the roller radius"), std::string::npos)
        << e.what();
  }
  // A flat face has no roller to shrink: its cusp names the remedies it has.
  const PlateCam flat(steep, {FollowerKind::FlatFaced, 0.0, 0.0}, 20.0);
  try {
    cam_polar_function(flat);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("not single-valued in polar angle"), std::string::npos) << message;
    EXPECT_EQ(message.find("roller"), std::string::npos) << message;
    EXPECT_NE(message.find("a flat face needs Rb + s + s'' > 0"), std::string::npos) << message;
  }
}

// Radial roller: the smallest Rb with max pressure angle 30° and no undercut. An independent
// dense sampling of atan(s'/(Rb + Rr + s)) must give 30° at that Rb.
TEST(PlateCam, MinimumBaseRadiusMeetsThePressureAngleExactly) {
  const CamProgram program = rdrd_program();
  const Follower roller{FollowerKind::Roller, 0.0, 8.0};
  const BaseRadiusResult r =
      minimum_base_radius(program, roller, Rotation::CounterClockwise,
                          {30 * kRadiansPerDegree, 0.0}, uniform_angles(360));
  EXPECT_NEAR(r.max_pressure_angle.value, 30 * kRadiansPerDegree, 1e-8);
  const double measured = test::dense_maximum([&](double t) {
    double s[2];
    program.derivatives(t, 1, s);
    return std::abs(std::atan(s[1] / (r.base_radius + 8.0 + s[0])));
  }, 0, 2 * pi).value;
  EXPECT_NEAR(measured, 30 * kRadiansPerDegree, 1e-8);
  EXPECT_GT(r.min_contour_speed, 0.0);

  // Flat face on s = d(1 - cos θ): ρ = Rb + s + s'' = Rb + d, so ρ >= 20 needs Rb = 20 - d = 15.
  const BaseRadiusResult flat =
      minimum_base_radius(eccentric_program(5.0), {FollowerKind::FlatFaced, 0.0, 0.0},
                          Rotation::Clockwise, {30 * kRadiansPerDegree, 20.0}, uniform_angles(100));
  EXPECT_NEAR(flat.base_radius, 15.0, 1e-7);
  EXPECT_NEAR(flat.min_convex_contour_radius.value, 20.0, 1e-7);
}

TEST(PlateCam, RejectsFollowersThatDoNotFit) {
  EXPECT_THROW(PlateCam(rdrd_program(), {FollowerKind::KnifeEdge, 50.0, 0.0}, 40.0), InputError);
  EXPECT_THROW(PlateCam(rdrd_program(), {FollowerKind::Roller, 0.0, 0.0}, 40.0), InputError);
  EXPECT_THROW(PlateCam(rdrd_program(), {FollowerKind::Roller, 0.0, 5.0}, -1.0), InputError);
}

}  // namespace
}  // namespace polarform
