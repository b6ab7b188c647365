// Frame candidates (issue 19): the least-squares axis line recovers a tilted surface of
// revolution's axis from a bad start, and finds the line of a given axis; the least-squares centre
// recovers a sphere's centre; a ±120° patch of a noisy bumpy cylinder with a tilted axis is fitted
// with defaults in a frame within 1° of the true axis and within 1.2 times the noise, every
// candidate reported with its error.
#include "src/fit/frame_candidates.h"

#include <gtest/gtest.h>

#include <cmath>

#include "src/fit/rotational_fit.h"
#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

using test::kPi;

double degrees_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), std::abs(a.dot(b))) * 180.0 / kPi;
}

// Distance from the true axis (through t along d) to the point o.
double off_axis(const Eigen::Vector3d& o, const Eigen::Vector3d& t, const Eigen::Vector3d& d) {
  const Eigen::Vector3d q = o - t;
  return (q - d * d.dot(q)).norm();
}

TEST(FrameCandidates, LeastSquaresAxisRecoversASurfaceOfRevolution) {
  Eigen::Matrix3Xd p = test::cylindrical_cloud(
      [](double z, double) { return 20.0 + 0.004 * z * z; }, 5000, -30, 30, -2.0, 2.0, 11);
  test::add_noise(p, 0.01, 12);
  const test::Rigid m = test::random_rigid(13);
  p = m(p);
  const Eigen::Vector3d tilted = (m.R.col(2) + 0.08 * m.R.col(0)).normalized();  // 4.6° off
  const FrameCandidate c = least_squares_axis(p, m.t + 3.0 * m.R.col(1), tilted, false, false);
  EXPECT_LT(degrees_between(c.axis, m.R.col(2)), 0.05) << c.how;
  EXPECT_LT(off_axis(c.origin, m.t, m.R.col(2)), 0.05) << c.how;
  // A given axis keeps its direction and finds its line.
  const FrameCandidate line =
      least_squares_axis(p, m.t + 5.0 * m.R.col(0), m.R.col(2), false, true);
  EXPECT_LT(degrees_between(line.axis, m.R.col(2)), 1e-12);
  EXPECT_LT(off_axis(line.origin, m.t, m.R.col(2)), 0.02) << line.how;
}

TEST(FrameCandidates, LeastSquaresCentreRecoversASphere) {
  Eigen::Matrix3Xd p =
      test::spherical_cloud([](double, double) { return 25.0; }, 4000, 0.3, 1.6, 0.0, 2.5, 21);
  test::add_noise(p, 0.01, 22);
  p.colwise() += Eigen::Vector3d(4, -7, 9);
  const FrameCandidate c =
      least_squares_centre(p, Eigen::Vector3d(6, -5, 6), Eigen::Vector3d::UnitZ());
  EXPECT_LT((c.origin - Eigen::Vector3d(4, -7, 9)).norm(), 0.02) << c.how;
}

double bumpy(double z, double t) {
  const double s = 40.0 * (t - 0.3);
  return 40.0 + 4.0 * std::sin(z / 10.0) + 3.0 * std::exp(-((z - 5) * (z - 5) + s * s) / 200.0) +
         0.8 * std::sin(z / 6.0) * std::cos(2 * t);
}

TEST(FrameCandidates, FaceLikeCylinderPatchWithDefaults) {
  const double sigma = 0.05;
  for (unsigned seed : {5u, 7u, 9u}) {
    Eigen::Matrix3Xd p =
        test::cylindrical_cloud(bumpy, 1600, -30, 30, -2 * kPi / 3, 2 * kPi / 3, seed);
    test::add_noise(p, sigma, seed + 1);
    const test::Rigid m = test::random_rigid(seed + 2);
    p = m(p);
    const RotationalFit f = fit_rotational(p);
    const double axis_error = degrees_between(f.frame().frame.axes.col(2), m.R.col(2));
    RecordProperty("axis_error_deg_" + std::to_string(seed), test::sci(axis_error));
    RecordProperty("rms_" + std::to_string(seed), test::sci(f.report().error.rms));
    EXPECT_EQ(f.method(), FitMethod::cylindrical) << f.reason;
    EXPECT_LT(axis_error, 1.0) << f.reason;
    EXPECT_LT(f.report().error.rms, 1.2 * sigma) << f.reason;
    EXPECT_EQ(f.report().unconverged, 0u);
    ASSERT_GE(f.frame_candidates.size(), 2u);
    for (const FrameCandidate& c : f.frame_candidates)
      EXPECT_TRUE(c.rms > 0.0 || !c.failure.empty()) << c.name;
  }
}

}  // namespace
}  // namespace polarform
