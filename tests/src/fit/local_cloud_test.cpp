// The start shared by the spherical and cylindrical fits: the points in their estimated frame
// (to 1e-12 of the frame's own transform), and the input checks naming the fit.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "src/error.h"
#include "src/fit/local_frame.h"
#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

using test::kPi;

TEST(LocalCloud, PointsInTheEstimatedFrame) {
  const test::Rigid m = test::random_rigid(17);
  const Eigen::Matrix3Xd cloud =
      m(test::spherical_cloud([](double, double) { return 30.0; }, 500, 0, kPi, 0, 2 * kPi, 18));
  const LocalCloud c = local_cloud(cloud, {}, 2, "spherical fit");
  ASSERT_EQ(c.points.cols(), cloud.cols());
  EXPECT_LT((c.frame.frame.to_global(c.points) - cloud).cwiseAbs().maxCoeff(), 1e-12);
  for (int j = 0; j < c.points.cols(); ++j) {
    const Eigen::Vector3d local = c.points.col(j);
    EXPECT_LT((c.frame.frame.to_global(local) - cloud.col(j)).norm(), 1e-12) << j;
    EXPECT_NEAR(local.norm(), 30.0, 1e-6) << j;  // a noise-free sphere about its centre
  }
  EXPECT_LT((c.frame.frame.origin - m.t).norm(), 1e-6);
}

TEST(LocalCloud, RefusesTooFewOrNonFinitePoints) {
  const Eigen::Matrix3Xd few = Eigen::Matrix3Xd::Random(3, 15);
  try {
    local_cloud(few, {}, 1, "cylindrical fit");
    ADD_FAILURE() << "15 points accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "cylindrical fit: 15 points, expected at least 16");
  }
  Eigen::Matrix3Xd bad = Eigen::Matrix3Xd::Random(3, 40);
  bad(1, 7) = std::numeric_limits<double>::quiet_NaN();
  try {
    local_cloud(bad, {}, 1, "spherical fit");
    ADD_FAILURE() << "a NaN accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "spherical fit: a point is not finite");
  }
}

}  // namespace
}  // namespace polarform
