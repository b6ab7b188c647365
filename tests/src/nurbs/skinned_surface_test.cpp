// skin_sections (NURBS Book §10.3; spec B4): the skin interpolates its sections, two sections give
// the ruled surface, equal circles along a line give a cylinder, and bad input is refused.
#include "src/nurbs/skinned_surface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "src/error.h"
#include "src/nurbs/ruled_surface.h"

namespace polarform {
namespace {

using Eigen::Vector3d;

// The full circle of radius r about (0, 0, z) in the plane z: 4 RQB quarter arcs.
NurbsCurve3d circle(double r, double z, const Vector3d& shift = Vector3d::Zero()) {
  const double w = std::sqrt(0.5);
  NurbsCurve3d::Points p = {{r, 0, z},   {r, r, z},  {0, r, z},  {-r, r, z}, {-r, 0, z},
                            {-r, -r, z}, {0, -r, z}, {r, -r, z}, {r, 0, z}};
  for (Vector3d& q : p) q += shift;
  return NurbsCurve3d(2, {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4}, p, {1, w, 1, w, 1, w, 1, w, 1});
}

// A non-rational cubic section of other knots.
NurbsCurve3d wave(double z) {
  return NurbsCurve3d(3, {0, 0, 0, 0, 1.5, 4, 4, 4, 4},
                      {{0, 0, z}, {1, 2, z}, {2, -1, z + 0.5}, {3, 1, z}, {4, 0, z}});
}

TEST(SkinnedSurface, InterpolatesItsSections) {
  const std::vector<NurbsCurve3d> c = {circle(5, 0), circle(7, 3, {1, 0, 0}), wave(5),
                                       circle(4, 9, {0, 2, 0})};
  const std::vector<double> v = {0, 3, 5.5, 9};
  const NurbsSurface S = skin_sections(c, v);
  EXPECT_EQ(S.degree_v(), 3);
  double worst = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k)
    for (int a = 0; a <= 400; ++a) {
      const double u = 4.0 * a / 400;
      worst = std::max(worst, (S.point(u, v[k]) - c[k].point(u)).norm());
    }
  EXPECT_LE(worst, 1e-12 * 10);
}

TEST(SkinnedSurface, TwoSectionsGiveTheRuledSurface) {
  const NurbsCurve3d a = circle(5, 0), b = circle(8, 4, {1, 1, 0});
  const NurbsSurface S = skin_sections({a, b}, {0, 1}), R = ruled_surface(a, b);
  double worst = 0.0;
  for (int i = 0; i <= 100; ++i)
    for (int j = 0; j <= 100; ++j) {
      const double u = 4.0 * i / 100, v = j / 100.0;
      worst = std::max(worst, (S.point(u, v) - R.point(u, v)).norm());
    }
  EXPECT_LE(worst, 1e-12 * 10);
}

TEST(SkinnedSurface, EqualCirclesAlongALineGiveACylinder) {
  const std::vector<NurbsCurve3d> c = {circle(6, 0), circle(6, 1), circle(6, 4), circle(6, 10)};
  const NurbsSurface S = skin_sections(c, {0, 1, 4, 10});
  double worst = 0.0;
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j <= 200; ++j) {
      const Vector3d p = S.point(4.0 * i / 200, 10.0 * j / 200);
      worst = std::max(worst, std::abs(p.head<2>().norm() - 6));
    }
  EXPECT_LE(worst, 1e-12 * 6);
}

TEST(SkinnedSurface, BadInputIsRefused) {
  EXPECT_THROW(skin_sections({circle(1, 0)}, {0}), InputError);
  EXPECT_THROW(skin_sections({circle(1, 0), circle(1, 1)}, {0}), InputError);
  EXPECT_THROW(skin_sections({circle(1, 0), circle(1, 1)}, {1, 1}), InputError);
  const NurbsCurve3d shorter(1, {0, 0, 2, 2}, {{0, 0, 0}, {1, 0, 0}});  // domain [0, 2]
  EXPECT_THROW(skin_sections({circle(1, 0), shorter}, {0, 1}), InputError);
}

}  // namespace
}  // namespace polarform
