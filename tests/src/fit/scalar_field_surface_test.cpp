// Scientific visualisation (Bae 2002, §5.3): values on spherical and cylindrical grids become
// S = (s·F + d)·B (5.6), whose radius along each base direction is s·F + d exactly, with the value
// of p at each control point's parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "src/error.h"
#include "src/fit/scalar_field_surface.h"
#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

using test::kPi;

std::vector<double> greville(int p, const Knots& U) {
  std::vector<double> g;
  for (int i = 0; i + p + 1 < static_cast<int>(U.size()); ++i) {
    double s = 0;
    for (int k = 1; k <= p; ++k) s += U[i + k];
    g.push_back(s / p);
  }
  return g;
}

TEST(ScalarFieldSurface, SphericalGridShowsTheValuesAsRadius) {
  auto pressure = [](double phi, double t) { return 2 + std::cos(phi) + 0.5 * std::sin(phi) * std::cos(t); };
  std::vector<double> P, F, T;
  for (int k = 0; k <= 30; ++k)
    for (int l = 0; l < 60; ++l) {
      const double phi = 0.05 + (kPi - 0.1) * k / 30, t = 2 * kPi * l / 60;
      P.push_back(pressure(phi, t)), F.push_back(phi), T.push_back(t);
    }
  auto vec = [](const std::vector<double>& v) { return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size()).eval(); };
  ScalarFieldOptions o;
  o.scale = 3.0;
  o.offset = 1.0;
  o.function.size_u = o.function.size_v = 14;
  const ScalarFieldSurface s = visualize_spherical(vec(P), vec(F), vec(T), o);
  EXPECT_EQ(s.surface.degree_u(), 5);
  EXPECT_EQ(s.surface.degree_v(), 5);
  EXPECT_LT(s.fit_error.max, 2e-3);
  for (double u = s.surface.front_u(); u <= s.surface.back_u(); u += 0.1)
    for (double v = s.surface.front_v(); v <= s.surface.back_v(); v += 0.1)
      EXPECT_NEAR(s.surface.point(u, v).norm(), 3.0 * s.F.point(u, v)[0] + 1.0, 1e-12);  // (5.6)
  const std::vector<double> gu = greville(s.surface.degree_u(), s.surface.knots_u());
  const std::vector<double> gv = greville(s.surface.degree_v(), s.surface.knots_v());
  ASSERT_EQ(s.control_values.size(), static_cast<Eigen::Index>(gu.size() * gv.size()));
  EXPECT_NEAR(s.control_values[7 * gv.size() + 11], s.F.point(gu[7], gv[11])[0], 1e-14);
  // p = 2 + cos φ + ½ sin φ cos θ ranges over 2 ± √1.25 on the sphere.
  EXPECT_NEAR(s.min_value, 2 - std::sqrt(1.25), 2e-3);
  EXPECT_NEAR(s.max_value, 2 + std::sqrt(1.25), 2e-3);
}

TEST(ScalarFieldSurface, CylindricalGridKeepsHeights) {
  std::vector<double> P, T, Z;
  for (int k = 0; k < 40; ++k)
    for (int l = 0; l < 50; ++l) {
      const double t = 2 * kPi * k / 40, z = -1 + 2.0 * l / 49;
      P.push_back(1 + 0.3 * z * z + 0.2 * std::cos(t)), T.push_back(t), Z.push_back(z);
    }
  auto vec = [](const std::vector<double>& v) { return Eigen::Map<const Eigen::VectorXd>(v.data(), v.size()).eval(); };
  ScalarFieldOptions o;
  o.offset = 0.5;
  o.function.size_u = 6;
  o.function.size_v = 14;
  const ScalarFieldSurface s = visualize_cylindrical(vec(P), vec(T), vec(Z), o);
  EXPECT_EQ(s.surface.degree_u(), 3);
  EXPECT_EQ(s.surface.degree_v(), 5);
  EXPECT_LT(s.fit_error.max, 1e-3);
  for (double u = 0; u <= 1; u += 0.1)
    for (double v = s.surface.front_v(); v <= s.surface.back_v(); v += 0.1) {
      const Eigen::Vector3d q = s.surface.point(u, v);
      EXPECT_NEAR(q.head<2>().norm(), s.F.point(u, v)[0] + 0.5, 1e-12);
      EXPECT_NEAR(q.z(), -1 + 2 * u, 1e-12);
    }
  EXPECT_THROW(visualize_cylindrical(vec(P), vec(T), Eigen::VectorXd::Zero(3), o), InputError);
}

}  // namespace
}  // namespace polarform
