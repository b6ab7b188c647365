// Tessellation for drawing: the parameters hold the ends, every equal step and every distinct
// interior knot exactly (sorted, no duplicates); sampled points are the curve's and surface's own;
// a sphere's normals match the closed form, at its poles the neighbour's along u.
#include "src/nurbs/tessellation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "src/error.h"
#include "src/nurbs/surface_of_revolution.h"
#include "tests/src/nurbs/kernel_test_support.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(TessellationParameters, EqualStepsPlusInteriorKnots) {
  const Knots U = {0, 0, 0, 0.25, 0.5, 0.5, 0.8, 1, 1, 1};
  EXPECT_EQ(tessellation_parameters(U, 0.0, 1.0, 4),
            (std::vector<double>{0, 0.25, 0.5, 0.75, 0.8, 1}));
  EXPECT_EQ(tessellation_parameters(U, 0.0, 1.0, 1), (std::vector<double>{0, 0.25, 0.5, 0.8, 1}));
  // A sub-range keeps only the knots strictly inside it; its ends are its own.
  EXPECT_EQ(tessellation_parameters(U, 0.5, 1.0, 4),
            (std::vector<double>{0.5, 0.625, 0.75, 0.8, 0.875, 1}));
}

// A step that rounds to a neighbour of a knot gives way to the knot itself.
TEST(TessellationParameters, KnotWinsOverANearbyStep) {
  const double knot = 0.1 + 0.2;  // 0.30000000000000004, one ulp above the step 3/10
  ASSERT_NE(knot, 3 / 10.0);
  const std::vector<double> t = tessellation_parameters({0, 0, knot, 1, 1}, 0.0, 1.0, 10);
  EXPECT_EQ(t.size(), 11u);
  EXPECT_TRUE(std::binary_search(t.begin(), t.end(), knot));
  EXPECT_FALSE(std::binary_search(t.begin(), t.end(), 3 / 10.0));
}

TEST(TessellationParameters, RandomKnotVectors) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const int degree = 1 + trial % 5, count = 1 + (trial * 37) % 300;
    const double a = -2.0 + trial * 0.01, b = a + 0.5 + trial * 0.1;
    // Some knots exactly on steps, some not, multiplicities up to the degree.
    std::vector<double> on_steps;
    for (int k = 1; k < count; k += 1 + count / 3) on_steps.push_back(a + (b - a) * k / count);
    const Knots U = test::random_knots(rng, degree, a, b, 6, degree, on_steps);
    const std::vector<double> t = tessellation_parameters(U, a, b, count);
    ASSERT_EQ(t.front(), a);
    ASSERT_EQ(t.back(), b);
    for (std::size_t k = 1; k < t.size(); ++k) ASSERT_LT(t[k - 1], t[k]) << "sorted, no duplicates";
    // Every distinct interior knot, exactly.
    std::size_t knots_between_steps = 0;
    for (const Breakpoint& k : breakpoints(U)) {
      if (k.value == a || k.value == b) continue;
      EXPECT_TRUE(std::binary_search(t.begin(), t.end(), k.value)) << "knot " << k.value;
      const double steps = (k.value - a) / (b - a) * count;
      if (std::abs(steps - std::round(steps)) > 1e-9) ++knots_between_steps;
    }
    // Every equal step, or the knot it coincides with.
    for (int k = 0; k <= count; ++k) {
      const double step = a + (b - a) * k / count;
      const auto at = std::lower_bound(t.begin(), t.end(), step - 1e-12 * (b - a));
      ASSERT_NE(at, t.end());
      EXPECT_LE(std::abs(*at - step), 1e-12 * (b - a)) << "step " << k << " of " << count;
    }
    EXPECT_EQ(t.size(), count + 1 + knots_between_steps);
  }
}

TEST(TessellationParameters, RejectsBadInput) {
  const Knots U = {0, 0, 1, 1};
  EXPECT_THROW(tessellation_parameters(U, 0.0, 1.0, 0), InputError);
  EXPECT_THROW(tessellation_parameters(U, 1.0, 1.0, 8), InputError);
  EXPECT_THROW(tessellation_parameters(U, 1.0, 0.0, 8), InputError);
  EXPECT_THROW(tessellation_parameters(U, 0.0, INFINITY, 8), InputError);
}

TEST(CurveTessellation, PointsAreTheCurvesOwn) {
  std::mt19937 rng(11);
  for (int degree = 1; degree <= 6; ++degree) {
    const Knots U = test::random_knots(rng, degree, -1.0, 2.5, 5, degree);
    const NurbsCurve2d c2(test::random_rational(rng, degree, U, 2));
    const NurbsCurve3d c3(test::random_rational(rng, degree, U, 3));
    const CurveTessellation<2> t2 = tessellate(c2, 50);
    const CurveTessellation<3> t3 = tessellate(c3, 50);
    EXPECT_EQ(t2.parameters, tessellation_parameters(U, -1.0, 2.5, 50));
    EXPECT_EQ(t3.parameters, t2.parameters);
    ASSERT_EQ(t2.points.size(), t2.parameters.size());
    ASSERT_EQ(t3.points.size(), t3.parameters.size());
    for (std::size_t k = 0; k < t2.parameters.size(); ++k) {
      // Independently: the homogeneous B-spline projected.
      const Eigen::VectorXd h2 = c2.homogeneous().point(t2.parameters[k]);
      const Eigen::VectorXd h3 = c3.homogeneous().point(t3.parameters[k]);
      EXPECT_LT((t2.points[k] - h2.head<2>() / h2(2)).norm(), 1e-14);
      EXPECT_LT((t3.points[k] - h3.head<3>() / h3(3)).norm(), 1e-14);
    }
  }
}

// A knot of multiplicity p makes the curve pass through a control point with a corner: the
// tessellation has that point as a vertex, and its polyline turns there by the corner's angle.
TEST(CurveTessellation, CornerAtAFullMultiplicityKnotIsAVertex) {
  const double corner = 0.37;  // not on any of the 10 equal steps
  const NurbsCurve2d c2(2, {0, 0, 0, corner, corner, 1, 1, 1},
                        {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}}, {1, 2, 1, 0.5, 1});
  const CurveTessellation<2> t = tessellate(c2, 10);
  const auto at = std::find(t.parameters.begin(), t.parameters.end(), corner);
  ASSERT_NE(at, t.parameters.end());
  const std::size_t k = at - t.parameters.begin();
  ASSERT_GT(k, 0u);
  ASSERT_LT(k + 1, t.points.size());
  EXPECT_LT((t.points[k] - Eigen::Vector2d(2, 0)).norm(), 1e-15);
  const Eigen::Vector2d in = (t.points[k] - t.points[k - 1]).normalized();
  const Eigen::Vector2d out = (t.points[k + 1] - t.points[k]).normalized();
  EXPECT_LT((in - Eigen::Vector2d(1, 0)).norm(), 1e-12);  // along the first leg, y = 0
  EXPECT_LT(std::abs(out.x()), 1e-12);                    // along the second leg, x = 2
  EXPECT_GT(out.y(), 0.0);

  // In 3D, degree 3 with a triple knot: the corner point is sampled exactly.
  const NurbsCurve3d c3(
      3, {0, 0, 0, 0, corner, corner, corner, 1, 1, 1, 1},
      {{0, 0, 0}, {1, 0, 1}, {2, 0, 1}, {3, 1, 2}, {3, 2, 1}, {4, 3, 0}, {5, 3, 0}});
  const CurveTessellation<3> t3 = tessellate(c3, 10);
  const auto at3 = std::find(t3.parameters.begin(), t3.parameters.end(), corner);
  ASSERT_NE(at3, t3.parameters.end());
  EXPECT_LT((t3.points[at3 - t3.parameters.begin()] - Eigen::Vector3d(3, 1, 2)).norm(), 1e-14);
}

// The unit sphere of the kernel tests: u the meridian from the south pole (u = −π/2) to the north
// pole, v the equator; S_u × S_v points to the centre, so the unit normal is −S.
TEST(SurfaceTessellation, SphereNormalsAreTheClosedForm) {
  const NurbsSurface S = test::base_sphere();
  const SurfaceTessellation t = tessellate(S, 12, 7);
  // u: 13 steps, the knot 0 among them; v: 8 steps and the knots π/2, π, 3π/2 between them.
  ASSERT_EQ(t.u.size(), 13u);
  ASSERT_EQ(t.v.size(), 11u);
  EXPECT_TRUE(std::binary_search(t.u.begin(), t.u.end(), 0.0));
  for (double knot : {kPi / 2, kPi, 3 * kPi / 2})
    EXPECT_TRUE(std::binary_search(t.v.begin(), t.v.end(), knot)) << knot;
  const std::size_t nu = t.u.size(), nv = t.v.size();
  ASSERT_EQ(t.points.size(), nu * nv);
  ASSERT_EQ(t.normals.size(), nu * nv);
  double worst_point = 0.0, worst_normal = 0.0;
  for (std::size_t i = 0; i < nu; ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const Eigen::Vector3d& p = t.points[i * nv + j];
      worst_point = std::max(worst_point, (p - S.point(t.u[i], t.v[j])).norm());
      EXPECT_NEAR(p.norm(), 1.0, 1e-14);
      if (i == 0 || i + 1 == nu) continue;
      worst_normal = std::max(worst_normal, (t.normals[i * nv + j] + p).norm());
    }
  EXPECT_EQ(worst_point, 0.0);
  EXPECT_LT(worst_normal, 1e-13);
  // At the poles S_v = 0: no normal of its own; the neighbour's along u, the closed form there.
  for (std::size_t j = 0; j < nv; ++j) {
    for (const auto& [pole, neighbour] :
         {std::pair{std::size_t{0}, std::size_t{1}}, std::pair{nu - 1, nu - 2}}) {
      ASSERT_EQ(S.normal(t.u[pole], t.v[j]), Eigen::Vector3d::Zero());
      EXPECT_LT((t.points[pole * nv + j] - Eigen::Vector3d(0, 0, pole == 0 ? -1 : 1)).norm(),
                1e-15);
      const Eigen::Vector3d& n = t.normals[pole * nv + j];
      EXPECT_EQ(n, t.normals[neighbour * nv + j]);
      EXPECT_LT((n + t.points[neighbour * nv + j]).norm(), 1e-13);
      EXPECT_NEAR(n.norm(), 1.0, 1e-14);
    }
  }
}

// A surface of revolution (NURBS Book A8.1): a torus, no poles. Its profile circle runs along +z on
// the outside, so S_u × S_v points away from the axis there and out of the tube everywhere.
TEST(SurfaceTessellation, TorusNormalsAreTheClosedForm) {
  const double R = 5.0, r = 1.5;
  const NurbsCurve2d circle = test::rqb_circle(r);
  NurbsCurve3d::Points profile;
  for (const Eigen::Vector2d& q : circle.control_points())
    profile.emplace_back(R + q.x(), 0, q.y());
  const NurbsSurface S = revolve(NurbsCurve3d(2, circle.knots(), profile, circle.weights()),
                                 Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  const SurfaceTessellation t = tessellate(S, 16, 24);
  const std::size_t nv = t.v.size();
  double worst = 0.0;
  for (std::size_t i = 0; i < t.u.size(); ++i)
    for (std::size_t j = 0; j < nv; ++j) {
      const Eigen::Vector3d& p = t.points[i * nv + j];
      const Eigen::Vector3d centre = R * Eigen::Vector3d(p.x(), p.y(), 0).normalized();
      worst = std::max(worst, (t.normals[i * nv + j] - (p - centre) / r).norm());
      EXPECT_NEAR((p - centre).norm(), r, 1e-13);
    }
  EXPECT_LT(worst, 1e-13);
}

// A revolved quarter circle meets the axis at its end: the apex is a pole whose whole row (all u
// at the last v) is one point, so the neighbour along u cannot lend a normal; the neighbour along
// v does — within one v step of the axis direction, as the closed form there is the axis.
TEST(SurfaceTessellation, ApexOfARevolvedProfileTakesTheNormalAlongV) {
  const double r = 10.0;
  // Quarter circle from (r, 0, 0) to (0, 0, r): weights 1, 1/√2, 1.
  const NurbsCurve3d quarter(2, {0, 0, 0, 1, 1, 1}, {{r, 0, 0}, {r, 0, r}, {0, 0, r}},
                             {1, std::sqrt(0.5), 1});
  const NurbsSurface S =
      revolve(quarter, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());  // u: angle, v: arc
  const SurfaceTessellation t = tessellate(S, 24, 16);
  const std::size_t nu = t.u.size(), nv = t.v.size();
  const double step = (std::numbers::pi / 2) / 16;  // the largest v step along the arc, rad
  for (std::size_t i = 0; i < nu; ++i) {
    const Eigen::Vector3d& n = t.normals[i * nv + nv - 1];
    EXPECT_NEAR(n.norm(), 1.0, 1e-12) << "u = " << t.u[i];
    EXPECT_LE(std::acos(std::min(1.0, std::abs(n.z()))), step * (1 + 1e-9)) << "u = " << t.u[i];
  }
}

}  // namespace
}  // namespace polarform
