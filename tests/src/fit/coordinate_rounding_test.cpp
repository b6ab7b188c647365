// The rounding unit of stored coordinates (src/fit/coordinate_rounding): float32 values give half
// a float ulp at the largest magnitude, decimals half their quantum (constant or round coordinates
// do not coarsen it), full doubles half a double ulp.
#include "src/fit/coordinate_rounding.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace polarform {
namespace {

Eigen::Matrix3Xd random_points(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-80.0, 120.0);
  Eigen::Matrix3Xd p(3, 5000);
  for (Eigen::Index k = 0; k < p.size(); ++k) p.data()[k] = u(rng);
  p(0, 0) = 120.0;
  return p;
}

TEST(CoordinateRounding, FloatDecimalAndDoubleCoordinates) {
  const Eigen::Matrix3Xd full = random_points(3);
  const Eigen::Matrix3Xd single = full.cast<float>().cast<double>();
  EXPECT_DOUBLE_EQ(coordinate_rounding(single), 0.5 * std::numeric_limits<float>::epsilon() * 120);
  const Eigen::Matrix3Xd four = (full * 1e4).array().round() / 1e4;
  EXPECT_DOUBLE_EQ(coordinate_rounding(four), 0.5e-4);
  // Coordinates constant on a ring (an axis-aligned part) or ending in zeros do not coarsen it.
  Eigen::Matrix3Xd aligned = four;
  aligned.row(1).setConstant(1.2);
  EXPECT_DOUBLE_EQ(coordinate_rounding(aligned), 0.5e-4);
  Eigen::Matrix3Xd doubles = full;
  doubles.row(1).setConstant(1.2);
  EXPECT_LE(coordinate_rounding(doubles), 1e-14 * 120);
  EXPECT_LE(coordinate_rounding(full), 1e-14 * 120);
  EXPECT_GE(coordinate_rounding(full), 0.5 * std::numeric_limits<double>::epsilon() * 120);
}

}  // namespace
}  // namespace polarform
