// BaseSphere and BaseCylinder: every point on the unit sphere / unit cylinder, the degrees and patch
// counts of (3.3) and (3.7), and the surface-parameter synchronization of Bae 2002, §3.1–3.2.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <Eigen/Geometry>

#include "src/base/base_cylinder.h"
#include "src/base/base_sphere.h"
#include "src/error.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

double wrap(double a) { return std::remainder(a, 2 * kPi); }

// Angle between two 3D directions, accurate for tiny angles.
double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

Eigen::Vector3d direction(double phi, double theta) {
  return {std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi)};
}

struct SphereConfig {
  std::string name;
  BaseSphere sphere;
};

std::vector<SphereConfig> spheres() {
  std::vector<SphereConfig> out;
  for (ArcKind kind : {ArcKind::rqb, ArcKind::quartic}) {
    const std::string k = kind == ArcKind::rqb ? "rqb" : "quartic";
    out.push_back({k + " full", BaseSphere(kind, 0.0, kPi, 0.0, 2 * kPi)});
    out.push_back({k + " partial", BaseSphere(kind, 0.4, 2.5, -1.0, 2.0)});
    out.push_back({k + " fewest", BaseSphere(BaseCircle::fewest_arcs(kind, 0.0, kPi),
                                             BaseCircle::fewest_arcs(kind, 0.5, 0.5 + 2 * kPi))});
    out.push_back({k + " unit hexagon",
                   BaseSphere(BaseCircle::equal_arcs(kind, 0.1, 3.0, 3, AlphaRule::printed,
                                                     ArcParametrization::unit),
                              BaseCircle::equal_arcs(kind, -3.0, -3.0 + 2 * kPi, 6, AlphaRule::printed,
                                                     ArcParametrization::unit))});
    out.push_back({k + " unequal", BaseSphere(BaseCircle(kind, {0.0, 0.2, 1.7, 2.0}),
                                              BaseCircle(kind, {1.0, 1.3, 3.0, 5.5}))});
  }
  return out;
}

TEST(BaseSphere, DegreesAndPatches) {
  const BaseSphere rqb(ArcKind::rqb, 0.0, kPi, 0.0, 2 * kPi);
  EXPECT_EQ(rqb.surface().degree_u(), 2);
  EXPECT_EQ(rqb.surface().degree_v(), 2);
  EXPECT_EQ(rqb.meridian().arcs(), 2);  // 2 x 4 RQB patches, Bae (3.3)
  EXPECT_EQ(rqb.azimuth().arcs(), 4);
  EXPECT_TRUE(rqb.azimuth().closed());
  const BaseSphere quartic(ArcKind::quartic, 0.0, kPi, 0.0, 2 * kPi);
  EXPECT_EQ(quartic.surface().degree_u(), 4);
  EXPECT_EQ(quartic.surface().degree_v(), 4);
  // The poles are single points: the first and last control rows collapse onto ±z (up to
  // sin(π) = 1.2e-16).
  const NurbsSurface& S = rqb.surface();
  for (int j = 0; j < S.size_v(); ++j) {
    EXPECT_NEAR((S.control_point(0, j) - Eigen::Vector3d(0, 0, 1)).norm(), 0.0, 1e-16);
    EXPECT_NEAR((S.control_point(S.size_u() - 1, j) - Eigen::Vector3d(0, 0, -1)).norm(), 0.0, 2e-16);
  }
}

TEST(BaseSphere, EveryPointOnTheUnitSphere) {
  for (const SphereConfig& c : spheres()) {
    const NurbsSurface& S = c.sphere.surface();
    double worst = 0;
    for (int i = 0; i <= 300; ++i)
      for (int j = 0; j <= 300; ++j) {
        const double u = S.front_u() + (S.back_u() - S.front_u()) * i / 300;
        const double v = S.front_v() + (S.back_v() - S.front_v()) * j / 300;
        worst = std::max(worst, std::abs(S(u, v).norm() - 1.0));
      }
    EXPECT_LT(worst, 1e-14) << c.name;
  }
}

TEST(BaseSphere, SynchronizationPutsThePointOnTheRay) {
  std::mt19937 rng(3);
  for (const SphereConfig& c : spheres()) {
    const BaseSphere& b = c.sphere;
    const auto& m = b.meridian().breakpoints();
    const auto& a = b.azimuth().breakpoints();
    std::uniform_real_distribution<double> phi(m.front(), m.back()), theta(a.front(), a.back());
    double ray = 0, back_phi = 0, back_theta = 0;
    for (int i = 0; i < 100000; ++i) {
      const double f = phi(rng), t = theta(rng);
      const Eigen::Vector2d uv = b.parameters(f, t);
      ray = std::max(ray, angle_between(b.surface()(uv.x(), uv.y()), direction(f, t)));
      const Eigen::Vector2d ft = b.angles(uv.x(), uv.y());
      back_phi = std::max(back_phi, std::abs(ft.x() - f));
      back_theta = std::max(back_theta, std::abs(ft.y() - t));
    }
    EXPECT_LT(ray, 1e-13) << c.name;
    EXPECT_LT(back_phi, 1e-13) << c.name;
    EXPECT_LT(back_theta, 1e-13) << c.name;
  }
}

TEST(BaseSphere, MalformedInputThrows) {
  EXPECT_THROW(BaseSphere(ArcKind::rqb, -0.1, 1.0, 0.0, 1.0), InputError);
  EXPECT_THROW(BaseSphere(ArcKind::rqb, 0.5, 3.3, 0.0, 1.0), InputError);
  EXPECT_THROW(BaseSphere(ArcKind::quartic, 0.0, kPi, 0.0, 6.5), InputError);
  EXPECT_THROW(BaseSphere(ArcKind::rqb, 1.0, 0.5, 0.0, 1.0), InputError);
  EXPECT_THROW(BaseSphere(BaseCircle(ArcKind::rqb, {2.0, 4.0}), BaseCircle(ArcKind::rqb, {0.0, 1.0})),
               InputError);
  const BaseSphere s(ArcKind::rqb, 0.5, 1.5, 0.0, 1.0);
  EXPECT_THROW(s.parameters(0.2, 0.5), InputError);
  EXPECT_THROW(s.parameters(1.0, 1.5), InputError);
}

struct CylinderConfig {
  std::string name;
  BaseCylinder cylinder;
};

std::vector<CylinderConfig> cylinders() {
  std::vector<CylinderConfig> out;
  for (ArcKind kind : {ArcKind::rqb, ArcKind::quartic}) {
    const std::string k = kind == ArcKind::rqb ? "rqb" : "quartic";
    out.push_back({k + " full", BaseCylinder(kind, 0.0, 2 * kPi, -2.0, 3.0)});
    out.push_back({k + " partial", BaseCylinder(kind, -0.5, 4.0, 10.0, 10.5)});
    out.push_back({k + " fewest", BaseCylinder(BaseCircle::fewest_arcs(kind, 1.0, 1.0 + 2 * kPi), 0, 1)});
    out.push_back({k + " unit unequal",
                   BaseCylinder(BaseCircle(kind, {0.0, 0.3, 2.0, 4.5, 2 * kPi}, AlphaRule::printed,
                                           ArcParametrization::unit),
                                -100.0, 50.0)});
  }
  return out;
}

TEST(BaseCylinder, DegreesAndEveryPointOnTheCylinder) {
  for (const CylinderConfig& c : cylinders()) {
    const BaseCylinder& b = c.cylinder;
    const NurbsSurface& S = b.surface();
    EXPECT_EQ(S.degree_u(), 1) << c.name;
    EXPECT_EQ(S.degree_v(), b.azimuth().kind() == ArcKind::rqb ? 2 : 4) << c.name;
    EXPECT_EQ(S.front_u(), 0.0);
    EXPECT_EQ(S.back_u(), 1.0);
    const double height = b.z_end() - b.z_start();
    const double scale = std::max(std::abs(b.z_start()), std::abs(b.z_end()));
    double radius = 0, z = 0;
    for (int i = 0; i <= 100; ++i)
      for (int j = 0; j <= 1000; ++j) {
        const double u = i / 100.0;
        const double v = S.front_v() + (S.back_v() - S.front_v()) * j / 1000;
        const Eigen::Vector3d p = S(u, v);
        radius = std::max(radius, std::abs(p.head<2>().norm() - 1.0));
        z = std::max(z, std::abs(p.z() - (b.z_start() + u * height)) / scale);
      }
    EXPECT_LT(radius, 1e-14) << c.name;
    EXPECT_LT(z, 1e-14) << c.name;
  }
}

TEST(BaseCylinder, SynchronizationPutsThePointOnTheRay) {
  std::mt19937 rng(4);
  for (const CylinderConfig& c : cylinders()) {
    const BaseCylinder& b = c.cylinder;
    const auto& a = b.azimuth().breakpoints();
    std::uniform_real_distribution<double> theta(a.front(), a.back()), z(b.z_start(), b.z_end());
    const double height = b.z_end() - b.z_start();
    double ray = 0, dz = 0, back_theta = 0, back_z = 0;
    for (int i = 0; i < 100000; ++i) {
      const double t = theta(rng), h = z(rng);
      const Eigen::Vector2d uv = b.parameters(t, h);
      const Eigen::Vector3d p = b.surface()(uv.x(), uv.y());
      ray = std::max(ray, std::abs(wrap(std::atan2(p.y(), p.x()) - t)));
      dz = std::max(dz, std::abs(p.z() - h) / height);
      const Eigen::Vector2d th = b.angles_height(uv.x(), uv.y());
      back_theta = std::max(back_theta, std::abs(th.x() - t));
      back_z = std::max(back_z, std::abs(th.y() - h) / height);
    }
    EXPECT_LT(ray, 1e-13) << c.name;
    EXPECT_LT(dz, 1e-13) << c.name;
    EXPECT_LT(back_theta, 1e-13) << c.name;
    EXPECT_LT(back_z, 1e-13) << c.name;
  }
}

TEST(BaseCylinder, MalformedInputThrows) {
  EXPECT_THROW(BaseCylinder(ArcKind::rqb, 0.0, 1.0, 2.0, 2.0), InputError);
  EXPECT_THROW(BaseCylinder(ArcKind::rqb, 0.0, 1.0, 2.0, 1.0), InputError);
  EXPECT_THROW(BaseCylinder(ArcKind::rqb, 0.0, 7.0, 0.0, 1.0), InputError);
  const BaseCylinder c(ArcKind::quartic, 0.0, 1.0, 0.0, 1.0);
  EXPECT_THROW(c.parameters(0.5, 1.5), InputError);
  EXPECT_THROW(c.parameters(1.5, 0.5), InputError);
  EXPECT_THROW(c.angles_height(-0.5, 0.5), InputError);
}

}  // namespace
}  // namespace polarform
