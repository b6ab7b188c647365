// Foot points on a face-like partial cylinder (issue 19): a ±120° patch of a noisy bumpy cylinder
// with a tilted axis, fitted about a given axis through an origin 30 mm off it (as a quadric frame
// leaves it): every point's foot point converges, none needs more than the restart, and each
// distance equals the one found from the closest node of a dense parameter grid.
#include "src/fit/point_distances.h"

#include <gtest/gtest.h>

#include <cmath>

#include "src/fit/cylindrical_fit.h"
#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

using test::kPi;

double bumpy(double z, double t) {
  const double s = 40.0 * (t - 0.3);
  return 40.0 + 4.0 * std::sin(z / 10.0) + 3.0 * std::exp(-((z - 5) * (z - 5) + s * s) / 200.0) +
         0.8 * std::sin(z / 6.0) * std::cos(2 * t);
}

TEST(PointDistances, EveryFootPointOfAFaceLikePatchConvergesToTheClosestPoint) {
  Eigen::Matrix3Xd p = test::cylindrical_cloud(bumpy, 1600, -30, 30, -2 * kPi / 3, 2 * kPi / 3, 5);
  test::add_noise(p, 0.05, 6);
  const test::Rigid m = test::random_rigid(7);
  p = m(p);
  CylindricalFitOptions o;
  o.frame.axis = m.R.col(2);
  o.frame.origin = m.t + 30.0 * m.R.col(0);
  const CylindricalFit f = fit_cylindrical(p, o);
  EXPECT_EQ(f.report.unconverged, 0u);
  EXPECT_LE(f.report.restarted, 1600u);
  RecordProperty("restarted", std::to_string(f.report.restarted));
  EXPECT_LT(f.report.error.rms, 1.2 * 0.05);

  const ProductGeometry g = ProductGeometry::cylindrical(f.F, f.base);
  const Eigen::Matrix3Xd local = f.frame.frame.to_local(p);
  Eigen::VectorXd u(local.cols()), v(local.cols());
  const int grid = 200;
  for (Eigen::Index k = 0; k < local.cols(); ++k) {
    double best = HUGE_VAL;
    for (int i = 0; i <= grid; ++i)
      for (int j = 0; j <= grid; ++j) {
        const double a = g.front_u() + (g.back_u() - g.front_u()) * i / grid;
        const double b = g.front_v() + (g.back_v() - g.front_v()) * j / grid;
        const double d = (g.point(a, b) - local.col(k)).squaredNorm();
        if (d < best) best = d, u[k] = a, v[k] = b;
      }
    if (k == 99) break;  // 100 points: the dense search is slow
  }
  const PointDistances from_grid =
      point_distances(g, local.leftCols(100), u.head(100), v.head(100));
  EXPECT_EQ(from_grid.unconverged, 0u);
  for (Eigen::Index k = 0; k < 100; ++k)
    EXPECT_NEAR(f.report.signed_distance[k], from_grid.signed_distance[k], 1e-7) << k;
}

}  // namespace
}  // namespace polarform
