// Edge bending at the heads' curvature jumps (edge_bending.h) against the textbook cases written
// out here: the hemisphere on a cylinder of equal wall, Q0 = p/(8β), M0 = 0 (Timoshenko &
// Woinowsky-Krieger 1959, § 134); the 2:1 ellipsoid's junction (κ = a/b² = 4/a) four times that;
// a torispherical head's knuckle–crown joint on the crown's r2 = L; the kinked cone left out.
#include "designers/vessel/edge_bending.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;
const VesselLoad kLoad{500, 1500, 10, 2};  // a mm, length mm, t mm, p MPa

double beta(double r2, double t, double nu) {
  return std::pow(3 * (1 - nu * nu), 0.25) / std::sqrt(r2 * t);
}

TEST(EdgeBending, HemisphereOnACylinder) {
  const std::vector<EdgeBending> e = edge_bending(head_shape({}, 500), kLoad, 0.3);
  ASSERT_EQ(e.size(), 1u);
  const double b = beta(500, 10, 0.3);
  EXPECT_EQ(e[0].theta, 0.0);
  EXPECT_NEAR(e[0].r2, 500, 1e-9);
  EXPECT_NEAR(e[0].beta, b, 1e-15);
  EXPECT_NEAR(e[0].shear, 2 / (8 * b), 1e-9);
  // M_max = e^(−π/4) sin(π/4) Q0/β = 0.322396… Q0/β at π/(4β).
  EXPECT_NEAR(e[0].max_moment, 0.3223969 * e[0].shear / b, 1e-6 * e[0].max_moment);
  EXPECT_NEAR(e[0].max_moment_offset, kPi / (4 * b), 1e-12);
  EXPECT_NEAR(e[0].bending_stress, 6 * e[0].max_moment / 100, 1e-12);
  EXPECT_NEAR(e[0].hoop_bending_stress, 0.3 * e[0].bending_stress, 1e-12);
  // The hoop force at the junction: the mean of p a (cylinder) and p a/2 (sphere).
  EXPECT_NEAR(e[0].hoop_stress_at_joint, 0.75 * 2 * 500 / 10, 1e-9);
  EXPECT_NEAR(e[0].meridional_membrane_stress, 2 * 500 / 20.0, 1e-9);
  // In units of p a / t: σ_b = 6·0.3224/(8·√(3(1 − ν²))) = 0.1463 for the hemisphere.
  EXPECT_NEAR(e[0].bending_stress / (2 * 500 / 10.0), 0.14634, 1e-4);
  EXPECT_FALSE(e[0].approximate());
}

TEST(EdgeBending, EllipsoidJunctionScalesWithTheCurvatureJump) {
  const std::vector<EdgeBending> hemi = edge_bending(head_shape({}, 500), kLoad);
  const std::vector<EdgeBending> e =
      edge_bending(head_shape({HeadKind::ellipsoidal, 2.0}, 500), kLoad);
  ASSERT_EQ(e.size(), 1u);
  EXPECT_NEAR(e[0].kappa_jump, 500.0 / (250.0 * 250.0), 1e-15);
  EXPECT_NEAR(e[0].shear, 4 * hemi[0].shear, 1e-9);
  EXPECT_NEAR(e[0].hoop_stress_at_joint, 0.0, 1e-9);  // mean of p a and −p a
}

TEST(EdgeBending, TorisphericalKnuckleAndCrown) {
  const HeadShape shape = head_shape(torispherical_100_6(500), 500);
  const std::vector<EdgeBending> e = edge_bending(shape, kLoad);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_NEAR(e[0].kappa_jump, 1.0 / 60, 1e-15);  // cylinder to knuckle
  EXPECT_NEAR(e[1].theta, shape.jumps[1].theta, 1e-15);
  EXPECT_NEAR(e[1].kappa_jump, 1.0 / 1000 - 1.0 / 60, 1e-15);  // knuckle to crown
  EXPECT_NEAR(e[1].r2, 1000, 1e-6);  // the crown's normal passes through its centre
  // The hoop stress at the joint: the mean of the knuckle's −1466.67 and the crown's 100 MPa.
  EXPECT_NEAR(e[1].hoop_stress_at_joint, 0.5 * (200 * (1 - 1000.0 / 120) + 100), 1e-6);
  EXPECT_NEAR(e[1].shear, 2 * 1000 * (1.0 / 60 - 1.0 / 1000) / (8 * beta(1000, 10, 0.3)), 1e-9);
  // The knuckle (about 60 mm of arc) is shorter than the decay length π/β = 245 mm.
  EXPECT_TRUE(e[1].approximate());
}

TEST(EdgeBending, KinksAreNotCurvatureJumps) {
  const HeadPreset cone{HeadKind::conical, 2.0, 0.0, 0.0, kPi / 6};
  EXPECT_TRUE(edge_bending(head_shape(cone, 500), kLoad).empty());
  const HeadPreset toricone{HeadKind::conical, 2.0, 0.0, 60.0, kPi / 6};
  const std::vector<EdgeBending> e = edge_bending(head_shape(toricone, 500), kLoad);
  ASSERT_EQ(e.size(), 2u);  // junction and knuckle–cone joint
  EXPECT_NEAR(e[1].kappa_jump, -1.0 / 60, 1e-15);
  EXPECT_THROW(edge_bending(head_shape({}, 500), kLoad, 0.5), InputError);
}

}  // namespace
}  // namespace polarform
