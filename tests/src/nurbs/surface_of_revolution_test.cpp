// revolve (NURBS Book A8.1): every surface point keeps its profile point's distance from the axis
// and its axial position, the sweep ends at the rotated profile, spheres and cylinders are exact.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "src/error.h"
#include "src/nurbs/surface_of_revolution.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

// The semicircle x² + z² = r², x >= 0, from the south pole to the north pole (two RQB arcs).
NurbsCurve3d meridian_semicircle(double r) {
  const double w = std::sqrt(0.5);
  NurbsCurve3d::Points P{{0, 0, -r}, {r, 0, -r}, {r, 0, 0}, {r, 0, r}, {0, 0, r}};
  return NurbsCurve3d(2, {0, 0, 0, 0.5, 0.5, 1, 1, 1}, P, {1, w, 1, w, 1});
}

TEST(SurfaceOfRevolution, SemicircleGivesExactSphere) {
  const double r = 37.5;
  const NurbsSurface S = revolve(meridian_semicircle(r), Eigen::Vector3d::Zero(),
                                 Eigen::Vector3d::UnitZ());
  EXPECT_EQ(S.degree_u(), 2);
  EXPECT_EQ(S.degree_v(), 2);
  EXPECT_EQ(S.size_u(), 9);  // four quarter arcs for a full turn
  EXPECT_EQ(S.size_v(), 5);
  EXPECT_TRUE(S.is_rational());
  double worst = 0.0, min_outward = 1.0;
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const double u = i / 40.0, v = j / 40.0;
      const Eigen::Vector3d p = S(u, v);
      worst = std::max(worst, std::abs(p.norm() - r));
      if (j > 0 && j < 40) min_outward = std::min(min_outward, S.normal(u, v).dot(p) / r);
    }
  EXPECT_LT(worst, 1e-13 * r);
  EXPECT_GT(min_outward, 1.0 - 1e-12);  // unit normal along the outward radius
  for (int j = 0; j < S.size_v(); ++j) {  // closed seam, bit for bit; poles collapse
    EXPECT_EQ(S.control_point(0, j), S.control_point(8, j));
    EXPECT_EQ(S.weight(0, j), S.weight(8, j));
  }
  for (int i = 0; i < S.size_u(); ++i) EXPECT_EQ(S.control_point(i, 0), Eigen::Vector3d(0, 0, -r));
}

TEST(SurfaceOfRevolution, LineParallelToAxisGivesCylinder) {
  NurbsCurve3d::Points P{{12, 0, -5}, {12, 0, 30}};
  const NurbsSurface S =
      revolve(NurbsCurve3d(1, {0, 0, 1, 1}, P), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  EXPECT_EQ(S.degree_v(), 1);
  for (int i = 0; i <= 36; ++i)
    for (int j = 0; j <= 7; ++j) {
      const Eigen::Vector3d p = S(i / 36.0, j / 7.0);
      EXPECT_NEAR(std::hypot(p.x(), p.y()), 12.0, 1e-13);
      EXPECT_NEAR(p.z(), -5 + 35 * j / 7.0, 1e-13);
    }
}

// A rational cubic about a tilted, offset axis, swept 135°: distances to the axis and axial
// positions are those of the profile, the polar angle about the axis grows from 0 to 135°, and
// the last column is the profile rotated by 135°.
TEST(SurfaceOfRevolution, ArbitraryAxisAndPartialAngle) {
  NurbsCurve3d::Points P{{3, 1, 0}, {5, -2, 4}, {2, 4, 6}, {6, 3, 9}, {4, 0, 12}};
  const NurbsCurve3d C(3, {0, 0, 0, 0, 0.4, 1, 1, 1, 1}, P, {1, 0.7, 1.6, 0.9, 1.2});
  const Eigen::Vector3d O(1, 2, -3), D(1, 1, 2);
  const double angle = 3 * kPi / 4;
  const NurbsSurface S = revolve(C, O, D, angle);
  EXPECT_EQ(S.size_u(), 5);  // two arcs of 67.5°
  const Eigen::Vector3d T = D.normalized();
  const Eigen::AngleAxisd rotation(angle, T);
  double worst_radius = 0.0, worst_axial = 0.0, worst_end = 0.0;
  for (int j = 0; j <= 30; ++j) {
    const double v = j / 30.0;
    const Eigen::Vector3d p = C(v) - O;
    const double axial = p.dot(T);
    const Eigen::Vector3d X = (p - axial * T).normalized(), Y = T.cross(X);
    double previous = -1.0;
    for (int i = 0; i <= 30; ++i) {
      const Eigen::Vector3d q = S(i / 30.0, v) - O;
      const double q_axial = q.dot(T);
      worst_radius = std::max(worst_radius, std::abs((q - q_axial * T).norm() - (p - axial * T).norm()));
      worst_axial = std::max(worst_axial, std::abs(q_axial - axial));
      const double phi = std::atan2(q.dot(Y), q.dot(X));
      EXPECT_GT(phi, previous - 1e-12);
      EXPECT_LE(phi, angle + 1e-12);
      previous = phi;
    }
    EXPECT_NEAR(previous, angle, 1e-12);
    EXPECT_EQ(S(0.0, v), C(v));
    worst_end = std::max(worst_end, (S(1.0, v) - (O + rotation * p)).norm());
  }
  EXPECT_LT(worst_radius, 1e-12);
  EXPECT_LT(worst_axial, 1e-12);
  EXPECT_LT(worst_end, 1e-12);
}

TEST(SurfaceOfRevolution, ArcCountFollowsTheAngle) {
  const NurbsCurve3d C = meridian_semicircle(1.0);
  const Eigen::Vector3d O = Eigen::Vector3d::Zero(), Z = Eigen::Vector3d::UnitZ();
  EXPECT_EQ(revolve(C, O, Z, kPi / 2).size_u(), 3);
  EXPECT_EQ(revolve(C, O, Z, kPi / 2 + 1e-9).size_u(), 5);
  EXPECT_EQ(revolve(C, O, Z, kPi).size_u(), 5);
  EXPECT_EQ(revolve(C, O, Z, 1.5 * kPi).size_u(), 7);
  EXPECT_EQ(revolve(C, O, Z, 1.5 * kPi + 1e-9).size_u(), 9);
}

TEST(SurfaceOfRevolution, RejectsBadAxisAndAngle) {
  const NurbsCurve3d C = meridian_semicircle(1.0);
  const Eigen::Vector3d O = Eigen::Vector3d::Zero();
  EXPECT_THROW(revolve(C, O, Eigen::Vector3d::Zero()), InputError);
  EXPECT_THROW(revolve(C, Eigen::Vector3d(NAN, 0, 0), Eigen::Vector3d::UnitZ()), InputError);
  EXPECT_THROW(revolve(C, O, Eigen::Vector3d::UnitZ(), 0.0), InputError);
  EXPECT_THROW(revolve(C, O, Eigen::Vector3d::UnitZ(), 2 * kPi + 1e-9), InputError);
}

}  // namespace
}  // namespace polarform
