// Maximum-area plane (spec P5): a planar patch, the thin 120° strip where the TLS plane fails,
// and the fold check of half and 250° cylinders.
#include "src/fit/max_area_plane.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "tests/src/fit/fit_test_support.h"
#include "tests/src/fit/patch_test_support.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

// The blanket of a cylinder strip: radius r, arc `degrees` about z, height h, na × nh vertices.
SurfaceBlanket cylinder_blanket(double r, double degrees, double h, int na, int nh) {
  SurfaceBlanket b;
  for (int a = 0; a < na; ++a) b.u.push_back(static_cast<double>(a) / (na - 1));
  for (int c = 0; c < nh; ++c) b.v.push_back(static_cast<double>(c) / (nh - 1));
  b.points.resize(3, na * nh);
  for (int a = 0; a < na; ++a)
    for (int c = 0; c < nh; ++c) {
      const double t = degrees * kPi / 180.0 * b.u[a];
      b.points.col(b.vertex(a, c)) = Eigen::Vector3d(r * std::cos(t), r * std::sin(t), h * b.v[c]);
    }
  return b;
}

// P5.1: a planar (wavy-in-plane) patch gives its plane normal to 1e-14.
TEST(MaxAreaPlane, PlanarPatchGivesItsNormal) {
  const Eigen::Vector3d n = Eigen::Vector3d(1, -2, 0.5).normalized();
  const Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  SurfaceBlanket b;
  for (int a = 0; a < 20; ++a) b.u.push_back(a / 19.0);
  for (int c = 0; c < 15; ++c) b.v.push_back(c / 14.0);
  b.points.resize(3, 300);
  for (int a = 0; a < 20; ++a)
    for (int c = 0; c < 15; ++c) {
      const double x = 7 * b.u[a] + 0.3 * std::sin(3 * b.v[c]),
                   y = 5 * b.v[c] + 0.2 * b.u[a] * b.u[a];
      b.points.col(b.vertex(a, c)) = Eigen::Vector3d(3, 4, 5) + x * e1 + y * e2;
    }
  const MaxAreaPlane p = max_area_plane(b);
  const double sign = p.normal.dot(n) > 0 ? 1.0 : -1.0;
  EXPECT_LE((p.normal - sign * n).norm(), 1e-14);
  EXPECT_LE((p.eigen_normal - sign * n).norm(), 1e-14);
  EXPECT_LE(std::abs(std::abs(p.lsq_normal.dot(n)) - 1.0), 1e-14);
  EXPECT_EQ(p.folded_triangles, 0);
  EXPECT_NEAR(p.projected_area / p.area, 1.0, 1e-14);
}

// P5.2: the thin 120° strip (radius 10, width 0.1): projected/true area = chord/arc = 0.827 on
// the max-area plane, ~0 on the TLS plane (its normal is the width direction).
TEST(MaxAreaPlane, ThinStripBeatsTheLsqPlane) {
  const SurfaceBlanket b = cylinder_blanket(10.0, 120.0, 0.1, 200, 3);
  const MaxAreaPlane p = max_area_plane(b);
  const double chord_over_arc = 2 * 10 * std::sin(kPi / 3) / (10 * 2 * kPi / 3);
  const double ratio = p.projected_area / p.area;
  EXPECT_NEAR(ratio, chord_over_arc, 1e-3);
  EXPECT_NEAR(ratio, 0.827, 1e-3);
  // The bisector of the arc (60°), pointing outwards.
  EXPECT_LE((p.normal - Eigen::Vector3d(std::cos(kPi / 3), std::sin(kPi / 3), 0)).norm(), 1e-12);
  EXPECT_LE(p.angle_between_deg, 1e-5);  // symmetric strip: the two choices coincide
  double tls_projected = 0.0;
  for (int a = 0; a < b.quads_u(); ++a)
    for (int c = 0; c < b.quads_v(); ++c) {
      const auto P = [&](int i, int j) { return Eigen::Vector3d(b.points.col(b.vertex(i, j))); };
      tls_projected +=
          0.5 * (P(a + 1, c) - P(a, c)).cross(P(a + 1, c + 1) - P(a, c)).dot(p.lsq_normal);
      tls_projected +=
          0.5 * (P(a + 1, c + 1) - P(a, c)).cross(P(a, c + 1) - P(a, c)).dot(p.lsq_normal);
    }
  const double tls_ratio = std::abs(tls_projected) / p.area;
  EXPECT_LT(tls_ratio, 0.01);
  EXPECT_NEAR(std::abs(p.lsq_normal.z()), 1.0, 1e-9);
  RecordProperty("max_area_ratio", test::sci(ratio));
  RecordProperty("tls_ratio", test::sci(tls_ratio));
}

// P5.3: a half cylinder has no folded triangle, a 250° patch has some.
TEST(MaxAreaPlane, FoldCheckSeparatesHalfFrom250Degrees) {
  EXPECT_EQ(max_area_plane(cylinder_blanket(5.0, 180.0, 3.0, 60, 5)).folded_triangles, 0);
  const MaxAreaPlane p250 = max_area_plane(cylinder_blanket(5.0, 250.0, 3.0, 60, 5));
  EXPECT_GT(p250.folded_triangles, 0);
  RecordProperty("folded_250", p250.folded_triangles);
}

// A 360° cylinder has no vector area: the eigenvector (radial) stands in, and folds are found.
TEST(MaxAreaPlane, ClosedCylinderFallsBackToTheEigenvector) {
  const MaxAreaPlane p = max_area_plane(cylinder_blanket(5.0, 360.0, 3.0, 61, 5));
  EXPECT_LE((p.normal - p.eigen_normal).norm(), 1e-12);
  EXPECT_LE(std::abs(p.normal.z()), 1e-9);
  EXPECT_GT(p.folded_triangles, 0);
}

}  // namespace
}  // namespace polarform
