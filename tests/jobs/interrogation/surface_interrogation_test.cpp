// Surface interrogation as the jobs report it: the area fractions of a sphere (all elliptic), a
// cylinder (all parabolic) and a saddle (all hyperbolic); a surface of revolution whose profile
// r(z) = 20 + 4 sin(2πz/80) bulges and waists, whose hyperbolic fraction follows from the profile's
// inflections (K = −r″/(r(1 + r′²)²)); and the files.
#include "jobs/interrogation/surface_interrogation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/base/arc_curves.h"
#include "src/fit/curve_fit.h"
#include "src/nurbs/extrusion.h"
#include "src/nurbs/surface_of_revolution.h"

namespace polarform {
namespace {

NurbsCurve3d arc3(double start, double sweep, double r) {
  const NurbsCurve2d a = rqb_arc(start, sweep);
  NurbsCurve3d::Points p;
  for (const Eigen::Vector2d& q : a.control_points()) p.push_back({r * q.x(), 0, r * q.y()});
  return NurbsCurve3d(a.degree(), a.knots(), p, a.weights());
}

TEST(SurfaceInterrogation, AreaFractionsOfSphereCylinderAndSaddle) {
  const double pi = std::numbers::pi;
  const NurbsSurface sphere =
      revolve(arc3(-pi / 3, 2 * pi / 3, 5), Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  const SurfaceInterrogation s = interrogate_surfaces({sphere}, CurvatureQuantity::gaussian);
  EXPECT_NEAR(s.elliptic_area_fraction, 1.0, 1e-12);
  EXPECT_NEAR(s.min_gaussian, 1 / 25.0, 1e-9 / 25);
  EXPECT_NEAR(s.max_gaussian, 1 / 25.0, 1e-9 / 25);
  // The zone of a sphere between latitudes ±60°: 2πR·h = 2π·5·(2·5·sin 60°).
  EXPECT_NEAR(s.area, 2 * pi * 5 * 10 * std::sin(pi / 3), 1e-3 * s.area);
  const NurbsSurface cylinder = extrude(arc3(0.1, 2.0, 3), Eigen::Vector3d::UnitY(), 0, 7);
  const SurfaceInterrogation c = interrogate_surfaces({cylinder}, CurvatureQuantity::mean);
  EXPECT_NEAR(c.parabolic_area_fraction, 1.0, 1e-12);
  const Knots k1{0, 0, 1, 1};
  const NurbsSurface saddle(1, 1, k1, k1, {{-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}, {1, 1, 1}});
  const SurfaceInterrogation h = interrogate_surfaces({saddle}, CurvatureQuantity::absolute);
  EXPECT_NEAR(h.hyperbolic_area_fraction, 1.0, 1e-12);
  EXPECT_LT(h.max_gaussian, 0.0);
}

TEST(SurfaceInterrogation, BulgeAndWaistFollowTheProfile) {
  // The profile sampled densely and fitted (B1), revolved; K < 0 where r″ > 0, i.e. on the waist
  // half of the period: z in (40, 80) — the hyperbolic share of the area is the waist's area share.
  Eigen::Matrix3Xd p(3, 801);
  for (int k = 0; k <= 800; ++k) {
    const double z = 80.0 * k / 800;
    p.col(k) = Eigen::Vector3d(20 + 4 * std::sin(2 * std::numbers::pi * z / 80), 0, z);
  }
  CurveFitOptions<3> o;
  o.tolerance = 1e-6;
  o.fix_ends = true;
  const NurbsCurve3d profile = fit_curve<3>(p, o).curve;
  const NurbsSurface s = revolve(profile, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  const SurfaceInterrogation q = interrogate_surfaces({s}, CurvatureQuantity::gaussian, 128);
  // Closed form: area element 2π r sqrt(1 + r′²) dz, waist z ∈ (40, 80).
  double all = 0, waist = 0;
  for (int k = 0; k < 80000; ++k) {
    const double z = 80.0 * (k + 0.5) / 80000, w = 2 * std::numbers::pi / 80;
    const double r = 20 + 4 * std::sin(w * z), dr = 4 * w * std::cos(w * z);
    const double a = 2 * std::numbers::pi * r * std::sqrt(1 + dr * dr) * (80.0 / 80000);
    all += a;
    if (z > 40) waist += a;
  }
  EXPECT_NEAR(q.area, all, 1e-4 * all);
  EXPECT_NEAR(q.hyperbolic_area_fraction, waist / all, 2e-4);
  EXPECT_GT(q.max_gaussian, 0.0);
  EXPECT_LT(q.min_gaussian, 0.0);
}

TEST(SurfaceInterrogation, FilesAndTheirColours) {
  const NurbsSurface cylinder = extrude(arc3(0.1, 2.0, 3), Eigen::Vector3d::UnitY(), 0, 7);
  const SurfaceInterrogation c = interrogate_surfaces({cylinder}, CurvatureQuantity::mean, 16);
  const auto files = interrogation_x3d(c, "cylinder");
  ASSERT_EQ(files.size(), 2u);
  EXPECT_NE(files.at("curvature.x3d").find("<Switch"), std::string::npos);
  EXPECT_NE(files.at("reflection.x3d").find("IndexedFaceSet"), std::string::npos);
  const InterrogationCloud cloud = interrogation_cloud(c);
  EXPECT_EQ(static_cast<std::size_t>(cloud.points.cols()), cloud.values.size());
  for (const double v : cloud.values) EXPECT_NEAR(std::abs(v), 1 / 6.0, 1e-12);
  EXPECT_EQ(interrogation_file_names(),
            (std::vector<std::string>{"curvature.ply", "curvature.x3d", "reflection.x3d"}));
}

}  // namespace
}  // namespace polarform
