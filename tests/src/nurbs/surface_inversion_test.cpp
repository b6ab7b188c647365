// Closest point on a surface: against dense brute-force sampling on random rational surfaces, the
// orthogonality of the residual at interior solutions, points on the surface, boundary and corner
// minima, caller-supplied starts, and closed base spheres and cylinders (closed forms).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "src/base/base_circle.h"
#include "src/base/base_cylinder.h"
#include "src/base/base_sphere.h"
#include "src/error.h"
#include "src/nurbs/point_inversion.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

// Interior knots on (a, b), at least 0.1 apart, multiplicity up to degree − 1.
Knots random_knots(std::mt19937& rng, int degree, int n, double a, double b) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> interior;
  const int count = n - degree - 1;
  while (static_cast<int>(interior.size()) < count) {
    const double k = a + (b - a) * unit(rng);
    if (k - a < 0.1 || b - k < 0.1) continue;
    if (std::any_of(interior.begin(), interior.end(), [&](double x) { return std::abs(x - k) < 0.1; }))
      continue;
    const int left = count - static_cast<int>(interior.size());
    interior.insert(interior.end(), std::min(left, 1 + static_cast<int>(unit(rng) * (degree - 1))), k);
  }
  std::sort(interior.begin(), interior.end());
  return clamped_knots(degree, a, b, interior);
}

// A wavy rational height field over [0, 3] x [0, 2].
NurbsSurface random_surface(std::mt19937& rng, int pu, int pv, int nu, int nv) {
  std::uniform_real_distribution<double> bump(-0.6, 0.6), jitter(-0.15, 0.15), weight(0.4, 2.5);
  NurbsSurface::Points points;
  std::vector<double> weights;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      points.emplace_back(3.0 * i / (nu - 1) + jitter(rng), 2.0 * j / (nv - 1) + jitter(rng), bump(rng));
      weights.push_back(weight(rng));
    }
  return NurbsSurface(pu, pv, random_knots(rng, pu, nu, 0.0, 1.0), random_knots(rng, pv, nv, -1.0, 1.0),
                      points, weights);
}

// Dense samples of the surface as matrix columns, for brute-force minima.
Eigen::Matrix3Xd dense_samples(const NurbsSurface& s, int n) {
  Eigen::Matrix3Xd out(3, (n + 1) * (n + 1));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      out.col(i * (n + 1) + j) = s(s.front_u() + (s.back_u() - s.front_u()) * i / n,
                                   s.front_v() + (s.back_v() - s.front_v()) * j / n);
  return out;
}

double brute_force(const Eigen::Matrix3Xd& dense, const Eigen::Vector3d& p) {
  return std::sqrt((dense.colwise() - p).colwise().squaredNorm().minCoeff());
}

bool on_boundary(const NurbsSurface& s, const SurfaceProjection& r) {
  return r.u == s.front_u() || r.u == s.back_u() || r.v == s.front_v() || r.v == s.back_v();
}

TEST(SurfaceInversion, RandomSurfacesAgainstBruteForce) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> x(-0.5, 3.5), y(-0.5, 2.5), z(-1.5, 1.5);
  int interior = 0, boundary = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const NurbsSurface s = random_surface(rng, 2 + trial % 3, 2 + (trial / 3) % 3, 6 + trial % 3, 5);
    const SurfaceProjector projector(s);
    EXPECT_FALSE(projector.closed_u());
    EXPECT_FALSE(projector.closed_v());
    const Eigen::Matrix3Xd dense = dense_samples(s, 400);
    for (int k = 0; k < 150; ++k) {
      const Eigen::Vector3d p(x(rng), y(rng), z(rng));
      const SurfaceProjection r = projector.project(p);
      ASSERT_LE(r.distance, brute_force(dense, p) + 1e-12) << "trial " << trial << " point " << k;
      EXPECT_NEAR((s(r.u, r.v) - r.point).norm(), 0.0, 1e-15);
      EXPECT_NEAR((r.point - p).norm(), r.distance, 1e-15);
      if (on_boundary(s, r)) {
        ++boundary;
        continue;
      }
      ++interior;
      const auto d = s.derivatives(r.u, r.v, 1);
      const Eigen::Vector3d res = r.point - p;
      EXPECT_LT(std::abs(d[2].dot(res)) / (d[2].norm() * res.norm()), 1e-9);  // S_u
      EXPECT_LT(std::abs(d[1].dot(res)) / (d[1].norm() * res.norm()), 1e-9);  // S_v
    }
  }
  EXPECT_GT(interior, 400);
  EXPECT_GT(boundary, 100);
}

TEST(SurfaceInversion, PointsOnTheSurfaceAndCallerStarts) {
  std::mt19937 rng(22);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    const NurbsSurface s = random_surface(rng, 3, 2 + trial % 3, 7, 6);
    const SurfaceProjector projector(s);
    for (int k = 0; k < 200; ++k) {
      const double u = s.front_u() + (s.back_u() - s.front_u()) * unit(rng);
      const double v = s.front_v() + (s.back_v() - s.front_v()) * unit(rng);
      EXPECT_LT(projector.project(s(u, v)).distance, 1e-12);
      // From a nearby start, the local search lands on the same point.
      const double u0 = std::clamp(u + 0.02 * (unit(rng) - 0.5), s.front_u(), s.back_u());
      const double v0 = std::clamp(v + 0.02 * (unit(rng) - 0.5), s.front_v(), s.back_v());
      EXPECT_LT(projector.project(s(u, v), u0, v0).distance, 1e-12);
    }
  }
}

// A bilinear-in-appearance bicubic patch in the plane z = 0 over [0, 3] x [0, 2] (x = 3u, y = v + 1
// with non-uniform speed): points outside its footprint project onto edges and corners.
TEST(SurfaceInversion, EdgeAndCornerMinima) {
  NurbsSurface::Points points;
  const double xs[] = {0.0, 0.4, 2.0, 3.0}, ys[] = {0.0, 1.5, 1.8, 2.0};
  for (double x : xs)
    for (double y : ys) points.emplace_back(x, y, 0.0);
  const NurbsSurface s(3, 3, clamped_knots(3, 0, 1), clamped_knots(3, -1, 1), points);
  const SurfaceProjector projector(s);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> along_x(0.1, 2.9), along_y(0.1, 1.9), out(0.1, 2.0), z(-1, 1);
  for (int k = 0; k < 200; ++k) {
    // Beyond the edge x = 3 (u = 1): the foot is (3, y, 0).
    const Eigen::Vector3d p(3 + out(rng), along_y(rng), z(rng));
    const SurfaceProjection r = projector.project(p);
    EXPECT_EQ(r.u, 1.0);
    EXPECT_NEAR((r.point - Eigen::Vector3d(3, p.y(), 0)).norm(), 0.0, 1e-12);
    // Beyond the edge y = 0 (v = −1).
    const Eigen::Vector3d q(along_x(rng), -out(rng), z(rng));
    const SurfaceProjection rq = projector.project(q);
    EXPECT_EQ(rq.v, -1.0);
    EXPECT_NEAR((rq.point - Eigen::Vector3d(q.x(), 0, 0)).norm(), 0.0, 1e-12);
    // Beyond the corner (0, 2).
    const Eigen::Vector3d c(-out(rng), 2 + out(rng), z(rng));
    const SurfaceProjection rc = projector.project(c);
    EXPECT_EQ(rc.u, 0.0);
    EXPECT_EQ(rc.v, 1.0);
    EXPECT_NEAR(rc.distance, (c - Eigen::Vector3d(0, 2, 0)).norm(), 1e-14);
    // Above the patch: the foot is straight below.
    const Eigen::Vector3d a(along_x(rng), along_y(rng), z(rng));
    EXPECT_NEAR(projector.project(a).distance, std::abs(a.z()), 1e-14);
  }
}

// Closed surfaces: the full base sphere (seam in v, poles at the u ends) and the base cylinder.
// The closest point of the unit sphere is the radial projection, also across the seam.
TEST(SurfaceInversion, ClosedSphereAndCylinder) {
  std::mt19937 rng(24);
  std::uniform_real_distribution<double> unit(0.0, 1.0), tiny(-1e-7, 1e-7);
  for (ArcKind kind : {ArcKind::rqb, ArcKind::quartic}) {
    const BaseSphere sphere(kind, 0.0, kPi, -2.0, -2.0 + 2 * kPi);
    const SurfaceProjector projector(sphere.surface());
    EXPECT_TRUE(projector.closed_v());
    EXPECT_FALSE(projector.closed_u());
    for (int k = 0; k < 400; ++k) {
      const double phi = k % 10 == 0 ? 1e-4 * unit(rng) : kPi * unit(rng);
      const double theta = k % 4 == 0 ? -2.0 + tiny(rng) : 2 * kPi * unit(rng);
      const double rho = 0.2 + 2.0 * unit(rng);
      const Eigen::Vector3d dir(std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta),
                                std::cos(phi));
      const SurfaceProjection r = projector.project(rho * dir);
      EXPECT_NEAR(r.distance, std::abs(rho - 1.0), 1e-13) << phi << " " << theta;
      EXPECT_NEAR((r.point - dir).norm(), 0.0, 1e-9) << phi << " " << theta;
    }
    const BaseCylinder cylinder(kind, 1.0, 1.0 + 2 * kPi, -1.0, 2.0);
    const SurfaceProjector cyl(cylinder.surface());
    EXPECT_TRUE(cyl.closed_v());
    EXPECT_FALSE(cyl.closed_u());
    for (int k = 0; k < 400; ++k) {
      const double theta = k % 4 == 0 ? 1.0 + tiny(rng) : 2 * kPi * unit(rng);
      const double r = 0.2 + 2.0 * unit(rng), z = -1.0 + 3.0 * unit(rng);
      const Eigen::Vector3d p(r * std::cos(theta), r * std::sin(theta), z);
      const SurfaceProjection proj = cyl.project(p);
      EXPECT_NEAR(proj.distance, std::abs(r - 1.0), 1e-13);
      EXPECT_NEAR((proj.point - Eigen::Vector3d(std::cos(theta), std::sin(theta), z)).norm(), 0.0, 1e-9);
    }
  }
}

// A torus (tube radius 1 about the circle of radius 3), closed in u and v: the revolution of a
// closed base circle centred at r = 3. Its closest point has the closed form
// distance = |hypot(ρ − 3, z) − 1|.
TEST(SurfaceInversion, TorusClosedInBothDirections) {
  for (ArcKind kind : {ArcKind::rqb, ArcKind::quartic}) {
    const BaseCircle tube = BaseCircle::equal_arcs(kind, 0.5, 0.5 + 2 * kPi, 4);
    const BaseCircle around = BaseCircle::equal_arcs(kind, -1.0, -1.0 + 2 * kPi, 3);
    const Eigen::MatrixXd& M = tube.curve().homogeneous().coefs();
    const Eigen::MatrixXd& A = around.curve().homogeneous().coefs();
    const int nu = static_cast<int>(M.cols()), nv = static_cast<int>(A.cols());
    Eigen::MatrixXd h(4, nu * nv);
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) {
        const double r = 3.0 * M(2, i) + M(0, i);  // homogeneous r = 3 + x of the tube circle
        h.col(i * nv + j) << r * A(0, j), r * A(1, j), M(1, i) * A(2, j), M(2, i) * A(2, j);
      }
    const NurbsSurface torus(BSplineSurface(tube.curve().degree(), around.curve().degree(),
                                            tube.curve().knots(), around.curve().knots(), h));
    const SurfaceProjector projector(torus);
    EXPECT_TRUE(projector.closed_u());
    EXPECT_TRUE(projector.closed_v());
    std::mt19937 rng(25);
    std::uniform_real_distribution<double> angle(-kPi, kPi), radius(0.1, 2.5), tiny(-1e-7, 1e-7);
    for (int k = 0; k < 400; ++k) {
      // Points near both seams (tube angle 0.5, azimuth −1) as well as anywhere.
      const double a = k % 3 == 0 ? 0.5 + tiny(rng) : angle(rng);
      const double b = k % 5 == 0 ? -1.0 + tiny(rng) : angle(rng);
      const double t = radius(rng);
      const double rho = 3.0 + t * std::cos(a), z = t * std::sin(a);
      const Eigen::Vector3d p(rho * std::cos(b), rho * std::sin(b), z);
      const SurfaceProjection r = projector.project(p);
      EXPECT_NEAR(r.distance, std::abs(t - 1.0), 1e-13) << a << " " << b << " " << t;
      const Eigen::Vector3d foot((3.0 + std::cos(a)) * std::cos(b), (3.0 + std::cos(a)) * std::sin(b),
                                 std::sin(a));
      EXPECT_NEAR((r.point - foot).norm(), 0.0, 1e-9);
    }
    // A caller's start just before both seams, the foot just after them: Newton must wrap.
    const double a = 0.6, b = -0.9, t = 1.7, rho = 3.0 + t * std::cos(a);
    const Eigen::Vector3d p(rho * std::cos(b), rho * std::sin(b), t * std::sin(a));
    const SurfaceProjection r =
        projector.project(p, tube.parameter(0.4 + 2 * kPi), around.parameter(-1.1 + 2 * kPi));
    EXPECT_NEAR(r.distance, 0.7, 1e-13);
    EXPECT_NEAR(r.u, tube.parameter(a), 1e-12);
    EXPECT_NEAR(r.v, around.parameter(b), 1e-12);
  }
}

TEST(SurfaceInversion, BadInputThrows) {
  const BaseCylinder cylinder(ArcKind::rqb, 0.0, 1.0, 0.0, 1.0);
  const SurfaceProjector projector(cylinder.surface());
  EXPECT_THROW(projector.project(Eigen::Vector3d(NAN, 0, 0)), InputError);
  EXPECT_THROW(projector.project(Eigen::Vector3d(1, 0, 0), 2.0, 0.5), InputError);
  EXPECT_THROW(SurfaceProjector(cylinder.surface(), -1), InputError);
}

}  // namespace
}  // namespace polarform
