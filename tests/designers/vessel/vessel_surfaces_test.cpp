// The vessel's surfaces from a converted profile (here F·B̃ over a quasi-uniform quartic base
// circle, as the converter builds it): the head revolves the A half exactly, the cylinder and the
// far head share its circles, and every normal points out of the vessel.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "designers/vessel/vessel_surfaces.h"
#include "src/base/base_circle.h"
#include "src/error.h"
#include "src/nurbs/symbolic_product.h"

namespace polarform {
namespace {

using ::testing::HasSubstr;
constexpr double kPi = std::numbers::pi;
constexpr double kLength = 1500;

NurbsCurve2d converted_profile() {
  Eigen::VectorXd c(10);
  c << 500, 500, 500, 440, 330, 300, 330, 440, 500, 500;
  const BSplineFunction F(5, uniform_clamped_knots(5, 5, 0, kPi), c);
  const BaseCircle base(ArcKind::quartic, {0, kPi / 4, kPi / 2, 3 * kPi / 4, kPi});
  return product(F, base.curve());
}

TEST(VesselSurfaces, HeadRevolvesTheHalfFromJunctionAToTheApex) {
  const NurbsCurve2d profile = converted_profile();
  const VesselSurfaces v = vessel_surfaces(profile, kLength);
  EXPECT_EQ(v.apex_parameter, kPi / 2);  // the arc junction at the apex
  EXPECT_EQ(v.junction_radius, 500.0);
  EXPECT_EQ(v.head_profile.front(), 0.0);
  EXPECT_EQ(v.head_profile.back(), kPi / 2);
  EXPECT_EQ(v.head_profile(0.0), profile(0.0));
  EXPECT_EQ(v.head_profile(kPi / 2).x(), 0.0);
  EXPECT_NEAR(v.head_profile(kPi / 2).y(), profile(kPi / 2).y(), 1e-12);
  double worst = 0.0;
  for (int j = 0; j <= 40; ++j) {
    const double u = kPi / 2 * j / 40;
    const Eigen::Vector2d p = profile(u);
    EXPECT_NEAR((v.head_profile(u) - p).norm(), 0.0, 1e-11);
    for (int i = 0; i <= 24; ++i) {
      const Eigen::Vector3d s = v.head(i / 24.0, u);
      worst = std::max({worst, std::abs(std::hypot(s.x(), s.y()) - p.x()), std::abs(s.z() - p.y())});
    }
  }
  EXPECT_LT(worst, 1e-11);
  EXPECT_EQ(v.head.degree_v(), profile.degree());
  EXPECT_EQ(v.head.degree_u(), 2);
}

TEST(VesselSurfaces, CylinderAndFarHeadShareTheCircles) {
  const VesselSurfaces v = vessel_surfaces(converted_profile(), kLength);
  const int nv_cyl = v.cylinder.size_v(), nv_far = v.far_head.size_v();
  ASSERT_EQ(v.cylinder.size_u(), v.head.size_u());
  ASSERT_EQ(v.far_head.size_u(), v.head.size_u());
  EXPECT_EQ(v.cylinder.knots_u(), v.head.knots_u());
  for (int i = 0; i < v.head.size_u(); ++i) {
    EXPECT_EQ(v.cylinder.control_point(i, nv_cyl - 1), v.head.control_point(i, 0));
    EXPECT_EQ(v.cylinder.control_point(i, 0), v.far_head.control_point(i, nv_far - 1));
    EXPECT_EQ(v.cylinder.weight(i, nv_cyl - 1), v.head.weight(i, 0));
    EXPECT_EQ(v.cylinder.weight(i, 0), v.far_head.weight(i, nv_far - 1));
  }
  for (int i = 0; i <= 36; ++i)
    for (int j = 0; j <= 10; ++j) {
      const Eigen::Vector3d s = v.cylinder(i / 36.0, j / 10.0);
      EXPECT_NEAR(std::hypot(s.x(), s.y()), 500.0, 1e-12);
      EXPECT_NEAR(s.z(), -kLength + kLength * j / 10, 1e-12);
    }
  // The far head is the head mirrored in z = −L/2, run from its apex to its junction.
  const double a = v.far_head.front_v(), b = v.far_head.back_v();
  for (int i = 0; i <= 12; ++i)
    for (int j = 0; j <= 20; ++j) {
      const double u = i / 12.0, t = kPi / 2 * j / 20;
      const Eigen::Vector3d near = v.head(u, t), far = v.far_head(u, a + b - t);
      EXPECT_NEAR((far - Eigen::Vector3d(near.x(), near.y(), -kLength - near.z())).norm(), 0.0, 1e-11);
    }
}

TEST(VesselSurfaces, NormalsPointOutOfTheVessel) {
  const VesselSurfaces v = vessel_surfaces(converted_profile(), kLength);
  double head = 1, cylinder = 1, far = 1;
  for (int i = 0; i <= 12; ++i)
    for (int j = 1; j < 10; ++j) {
      const double u = i / 12.0, t = kPi / 2 * j / 10;
      const Eigen::Vector3d p = v.head(u, t);
      head = std::min(head, v.head.normal(u, t).dot(p.normalized()));
      const Eigen::Vector3d c = v.cylinder(u, j / 10.0);
      cylinder = std::min(cylinder, v.cylinder.normal(u, j / 10.0).dot(Eigen::Vector3d(c.x(), c.y(), 0).normalized()));
      const double tf = v.far_head.front_v() + (v.far_head.back_v() - v.far_head.front_v()) * j / 10;
      const Eigen::Vector3d f = v.far_head(u, tf) + Eigen::Vector3d(0, 0, kLength);
      far = std::min(far, v.far_head.normal(u, tf).dot(f.normalized()));
    }
  EXPECT_GT(head, 0.3);
  EXPECT_GT(cylinder, 1 - 1e-12);
  EXPECT_GT(far, 0.3);
}

TEST(VesselSurfaces, RejectsProfilesThatAreNotAHeadSection) {
  const NurbsCurve2d profile = converted_profile();
  EXPECT_THROW(vessel_surfaces(profile, 0.0), InputError);
  const BaseCircle shifted(ArcKind::quartic, {0.1, kPi / 2, kPi});
  Eigen::VectorXd c = Eigen::VectorXd::Constant(6, 500);
  const NurbsCurve2d tilted = product(BSplineFunction(5, uniform_clamped_knots(5, 1, 0.1, kPi), c),
                                      shifted.curve());
  try {
    vessel_surfaces(tilted, kLength);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("the profile must run from junction A (x > 0, z = 0)"));
  }
}

}  // namespace
}  // namespace polarform
