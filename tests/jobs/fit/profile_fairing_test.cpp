// Fairing a fitted profile (`fit --fair`): on a noisy scan of a smooth closed profile, Farin and
// Kjellander lower the largest derivative jump of F, the curve moves by no more than the tolerance
// (measured), the new error of the points stays at the noise, and the product form stays exact.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "jobs/fit/fit_job.h"
#include "src/error.h"

namespace polarform {
namespace {

// r(θ) = 20 + 1.5 cos 3θ + 0.4 sin 5θ in the xy-plane, 1500 points, radial noise σ.
Eigen::Matrix3Xd noisy_profile(double sigma) {
  std::mt19937 rng(3);
  std::normal_distribution<double> noise(0.0, sigma);
  Eigen::Matrix3Xd p(3, 1500);
  for (int k = 0; k < 1500; ++k) {
    const double t = 2 * std::numbers::pi * k / 1500;
    const double r = 20 + 1.5 * std::cos(3 * t) + 0.4 * std::sin(5 * t) + noise(rng);
    p.col(k) = Eigen::Vector3d(r * std::cos(t), r * std::sin(t), 0.0);
  }
  return p;
}

TEST(ProfileFairing, BothMethodsSmoothWithinTheTolerance) {
  const double sigma = 0.01;
  FitJobOptions plain;
  plain.ctrl = std::pair{3, 60};  // more control points than the shape needs: noise gets in
  const FitJobResult raw = run_fit_job(noisy_profile(sigma), "noisy", plain);
  for (const FairingMethod method : {FairingMethod::farin, FairingMethod::kjellander}) {
    FitJobOptions o = plain;
    o.fairing = ProfileFairingOptions{method, 0.0, 100};
    const FitJobResult r = run_fit_job(noisy_profile(sigma), "noisy", o);
    const ProfileFit& p = std::get<ProfileFit>(r.fit);
    ASSERT_TRUE(p.fairing.has_value());
    const ProfileFairing& f = *p.fairing;
    EXPECT_NEAR(f.tolerance, 3 * raw.report().error.rms, 1e-12) << fairing_method_name(method);
    EXPECT_FALSE(f.steps.empty());
    EXPECT_LT(f.max_jump_after, f.max_jump_before);
    EXPECT_LE(f.measured_deviation, f.tolerance) << fairing_method_name(method);
    EXPECT_LT(r.report().error.rms, 1.5 * sigma);  // still at the noise
    ASSERT_TRUE(p.before_fairing.has_value());
    // The faired curve is still F·B: a point of the curve lies at radius F(u) from the centre.
    const PolarCurveFit& polar = p.polar;
    for (const double u : {0.3, 1.7, 4.1}) {
      const double ur = polar.F.front() + (polar.F.back() - polar.F.front()) * u / 6.3;
      EXPECT_NEAR((polar.curve.point(ur) - polar.centre).norm(), polar.F(ur), 1e-9);
    }
  }
}

}  // namespace
}  // namespace polarform
