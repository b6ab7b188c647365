// Follower dynamics against closed forms: the jump speed of a harmonic rise, the least spring rate
// at a speed, the torque of the power balance, and Hertz's line contact through Norton's
// half-width form.
#include "designers/cam/follower_dynamics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

// A harmonic rise of h over β, then its top dwell: s = h/2 (1 − cos πθ/β).
std::vector<MotionSample> harmonic_rise(double h, double beta) {
  std::vector<MotionSample> out;
  for (int i = 0; i <= 720; ++i) {
    const double t = beta * i / 720, x = kPi * t / beta;
    out.push_back({t, h / 2 * (1 - std::cos(x)), h / 2 * kPi / beta * std::sin(x),
                   h / 2 * (kPi / beta) * (kPi / beta) * std::cos(x),
                   std::numeric_limits<double>::infinity()});
  }
  return out;
}

// The follower leaves the cam where the deceleration's pull m·|s''|ω² beats the spring k·s + F₀:
// at θ = β, ω² = (k h + F₀) / (m·1e-3·h π²/(2β²)).
TEST(FollowerDynamics, HarmonicRiseJumpsAtTheClosedFormSpeed) {
  const double h = 20, beta = kPi / 2, m = 0.5, k = 5, f0 = 50;
  FollowerLoad load;
  load.mass = m;
  load.spring_rate = k;
  load.preload = f0;
  const double w = std::sqrt((k * h + f0) / (m * 1e-3 * h * kPi * kPi / (2 * beta * beta)));
  const double rpm = w * 60 / (2 * kPi);
  const FollowerDynamics slow = follower_dynamics(harmonic_rise(h, beta), 0.9 * rpm, 0, load);
  ASSERT_TRUE(slow.jump_rpm);
  EXPECT_NEAR(*slow.jump_rpm, rpm, 1e-9 * rpm);
  EXPECT_FALSE(slow.jumps);
  EXPECT_TRUE(follower_dynamics(harmonic_rise(h, beta), 1.01 * rpm, 0, load).jumps);
  // At the jump speed itself the least force is zero, at θ = β.
  const FollowerDynamics at = follower_dynamics(harmonic_rise(h, beta), rpm, 0, load);
  EXPECT_NEAR(at.least_force.force, 0.0, 1e-9);
  EXPECT_NEAR(at.least_force.theta, beta, 1e-12);
  // At 1.2 × that speed the spring needs (m·1e-3·h π²/(2β²)·ω² − F₀)/h.
  const double w2 = 1.2 * w;
  const FollowerDynamics fast = follower_dynamics(harmonic_rise(h, beta), 1.2 * rpm, 0, load);
  EXPECT_NEAR(fast.min_spring_rate,
              (m * 1e-3 * h * kPi * kPi / (2 * beta * beta) * w2 * w2 - f0) / h, 1e-9);
  // Torque = F·s'·1e-3 (N·m) at every sample.
  for (const DynamicsSample& d : fast.samples) EXPECT_TRUE(std::isfinite(d.torque));
  const MotionSample& mid = harmonic_rise(h, beta)[360];
  EXPECT_NEAR(fast.samples[360].torque, fast.samples[360].force * mid.v * 1e-3, 1e-12);
}

// An arm: the swing q = h/2 (1 − cos πθ/β) in degrees, the contact force's lever about the pivot
// fixed at ℓ. The torque I q̈ + k q + T₀ about the pivot (q in rad) first falls to zero at θ = β
// when ω² = (k h + T₀) / (I h π²/(2β²)); the contact force is the torque over the lever, the
// camshaft torque the arm's torque times dq/dθ.
TEST(FollowerDynamics, AnArmJumpsAtTheClosedFormSpeedAndPushesWithTorqueOverLever) {
  const double h_deg = 15, h = h_deg * kPi / 180, beta = kPi / 2, inertia = 0.02, k = 40, t0 = 8,
               lever = 120;
  FollowerLoad load;
  load.arm = true;
  load.inertia = inertia;
  load.torsion_rate = k;
  load.preload_torque = t0;
  std::vector<MotionSample> motion = harmonic_rise(h_deg, beta);
  for (MotionSample& m : motion) m.lever = lever;
  const double w = std::sqrt((k * h + t0) / (inertia * h * kPi * kPi / (2 * beta * beta)));
  const double rpm = w * 60 / (2 * kPi);
  const FollowerDynamics slow = follower_dynamics(motion, 0.8 * rpm, 10, load);
  ASSERT_TRUE(slow.jump_rpm);
  EXPECT_NEAR(*slow.jump_rpm, rpm, 1e-9 * rpm);
  EXPECT_FALSE(slow.jumps);
  EXPECT_TRUE(follower_dynamics(motion, 1.01 * rpm, 10, load).jumps);
  const double w2 = 0.8 * w;
  for (int i : {0, 200, 360, 600, 720}) {
    const MotionSample& m = motion[i];
    const double q = m.s * kPi / 180, dq = m.v * kPi / 180, ddq = m.a * kPi / 180;
    const double torque = inertia * ddq * w2 * w2 + k * q + t0;  // N·m about the pivot
    EXPECT_NEAR(slow.samples[i].force, torque / (lever * 1e-3),
                1e-9 * std::abs(torque) / (lever * 1e-3));
    EXPECT_NEAR(slow.samples[i].torque, torque * dq, 1e-12);
  }
  // The least torsion rate that keeps contact at 1.2 × the jump speed: (I h π²/(2β²) ω² − T₀)/h.
  const double w3 = 1.2 * w;
  EXPECT_NEAR(follower_dynamics(motion, 1.2 * rpm, 10, load).min_spring_rate,
              (inertia * h * kPi * kPi / (2 * beta * beta) * w3 * w3 - t0) / h, 1e-9);
  motion[100].lever = 0;  // the cam cannot push the arm there
  EXPECT_THROW(follower_dynamics(motion, rpm, 10, load), InputError);
}

// p = 2F/(π b L), b = √(2F/(πL) · (m₁ + m₂)/B), B = ½(1/R₁ + 1/R₂), m = (1 − ν²)/E (Norton's
// half-width form; steel on steel).
TEST(FollowerDynamics, HertzLineContactIsNortonsHalfWidthForm) {
  const double F = 2000, L = 12, r1 = 10, r2 = 35, E = 207000, nu = 0.28;
  const double m = (1 - nu * nu) / E, B = 0.5 * (1 / r1 + 1 / r2);
  const double b = std::sqrt(2 * F / (kPi * L) * 2 * m / B);
  EXPECT_NEAR(line_contact_stress(F, L, r1, r2, E, nu), 2 * F / (kPi * b * L), 1e-9);
  // A flat face on the cam: only the contour's curvature; a concave contour conforms.
  EXPECT_LT(line_contact_stress(F, L, r1, -35, E, nu), line_contact_stress(F, L, r1, 35, E, nu));
  EXPECT_NEAR(line_contact_stress(F, L, std::numeric_limits<double>::infinity(), r2, E, nu),
              std::sqrt(F / r2 / (kPi * L * 2 * m)), 1e-9);
  EXPECT_EQ(line_contact_stress(-5, L, r1, r2, E, nu), 0.0);  // no contact, no stress
}

TEST(FollowerDynamics, BadLoadsNameTheQuantity) {
  FollowerLoad load;
  load.mass = -1;
  EXPECT_THROW(follower_dynamics(harmonic_rise(10, 1), 300, 0, load), InputError);
  load.mass = 1;
  load.poisson_ratio = 0.5;
  EXPECT_THROW(follower_dynamics(harmonic_rise(10, 1), 300, 0, load), InputError);
}

}  // namespace
}  // namespace polarform
