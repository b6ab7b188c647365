// The sweep-kind evidence (designers/sweep/sweep_kind.h) on the three cases that decide it: a
// scanned stepped turned part (normals in planes through the axis, not flat), an elliptic prism
// (flat normals, not meridional) and a cylinder (both: a circle is a section and a meridian).
#include "designers/sweep/sweep_kind.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "tests/designers/sweep/turned_part.h"

namespace polarform {
namespace {

Eigen::Matrix3Xd prism(double a, double b, double length, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, 1, 3).normalized()).toRotationMatrix();
  Eigen::Matrix3Xd P(3, n);
  for (int k = 0; k < n; ++k) {
    const double t = 2 * std::numbers::pi * U(rng);
    P.col(k) = R * Eigen::Vector3d(a * std::cos(t), b * std::sin(t), length * U(rng));
  }
  return P;
}

TEST(SweepKind, TurnedPartIsRotationalNotAnExtrusion) {
  const Eigen::Matrix3Xd P =
      test::scan_samples(test::stepped_profile(), test::tilted_axis(), 20000, 0.0, 3);
  const SweepKindEvidence e = sweep_kind_evidence(P);
  std::printf("turned part: %s\n", e.text().c_str());
  EXPECT_TRUE(e.revolution_like());
  EXPECT_FALSE(e.extrusion_like());
}

TEST(SweepKind, EllipticPrismIsAnExtrusionNotRotational) {
  const SweepKindEvidence e = sweep_kind_evidence(prism(20, 10, 60, 20000, 4));
  std::printf("prism: %s\n", e.text().c_str());
  EXPECT_TRUE(e.extrusion_like());
  EXPECT_FALSE(e.revolution_like());
  EXPECT_LE(e.normals_flatness, 1e-4);
}

TEST(SweepKind, CylinderIsBoth) {
  const SweepKindEvidence e = sweep_kind_evidence(prism(10, 10, 60, 20000, 5));
  std::printf("cylinder: %s\n", e.text().c_str());
  EXPECT_TRUE(e.extrusion_like());
  EXPECT_TRUE(e.revolution_like());
}

}  // namespace
}  // namespace polarform
