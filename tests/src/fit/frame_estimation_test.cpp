// Local frame estimation under noise (Bae 2002, §4.3, Fig. 4.3): spheres and cylinders of radius
// R = 50 (cylinders 2R long), 20000 points, Gaussian noise N(0, σ²) on x, y, z, N_M = 3σ. Measured
// (max over 5 placements): N_M/R = 0.1 gives origin errors ≈ 0.13% of R (whole sphere) and ≈ 1%
// (hemisphere), axis errors ≈ 0.08° (cylinder); at N_M/R = 0.01 ten times less. The quadric type
// stays a real ellipsoid / real elliptic cylinder throughout: the rank tolerance follows the noise.
#include <gtest/gtest.h>

#include <cmath>

#include "src/fit/local_frame.h"
#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

using test::kPi;

constexpr double R = 50.0;

struct Errors {
  double sphere = 0, hemisphere = 0, axis_deg = 0;  // origin errors in % of R, axis in degrees
};

Errors measure(double nm_over_r) {
  const double sigma = nm_over_r * R / 3;
  Errors e;
  for (unsigned t = 0; t < 5; ++t) {
    const test::Rigid m = test::random_rigid(500 + t);
    Eigen::Matrix3Xd s = m(test::spherical_cloud([](double, double) { return R; }, 20000, 0, kPi, 0, 2 * kPi, 600 + t));
    test::add_noise(s, sigma, 700 + t);
    const FrameEstimate fs = estimate_frame(s);
    EXPECT_EQ(fs.quadric->classification.type, QuadricType::real_ellipsoid);
    e.sphere = std::max(e.sphere, (fs.frame.origin - m.t).norm() / R * 100);
    Eigen::Matrix3Xd h = m(test::spherical_cloud([](double, double) { return R; }, 20000, 0, kPi / 2, 0, 2 * kPi, 800 + t));
    test::add_noise(h, sigma, 900 + t);
    const FrameEstimate fh = estimate_frame(h);
    EXPECT_EQ(fh.quadric->classification.type, QuadricType::real_ellipsoid);
    e.hemisphere = std::max(e.hemisphere, (fh.frame.origin - m.t).norm() / R * 100);
    Eigen::Matrix3Xd c = m(test::cylindrical_cloud([](double, double) { return R; }, 20000, -R, R, 0, 2 * kPi, 1000 + t));
    test::add_noise(c, sigma, 1100 + t);
    const FrameEstimate fc = estimate_frame(c);
    EXPECT_EQ(fc.quadric->classification.type, QuadricType::real_elliptic_cylinder);
    const Eigen::Vector3d k = fc.frame.axes.col(2);
    e.axis_deg = std::max(e.axis_deg, std::atan2(k.cross(m.R.col(2)).norm(), std::abs(k.dot(m.R.col(2)))) * 180 / kPi);
  }
  return e;
}

// The frame's reason states the quadric's signature in words (Bae 2002, Table 4.1's k and K):
// a sphere's Qu eigenvalues share one sign, those of its 4 x 4 Q do not.
TEST(FrameEstimation, ReasonWritesTheSignatureInWords) {
  const Eigen::Matrix3Xd s =
      test::spherical_cloud([](double, double) { return R; }, 2000, 0, kPi, 0, 2 * kPi, 1);
  const std::string reason = estimate_frame(s).reason;
  EXPECT_NE(reason.find("the non-zero eigenvalues of Qu share one sign, those of Q differ in sign"),
            std::string::npos)
      << reason;
  EXPECT_EQ(reason.find("!="), std::string::npos) << reason;
}

TEST(FrameEstimation, OriginAndAxisErrorsGrowWithTheNoiseAsInFig43) {
  const Errors lo = measure(0.01), hi = measure(0.1);
  RecordProperty("sphere_origin_pct_at_0.01", test::sci(lo.sphere));
  RecordProperty("hemisphere_origin_pct_at_0.01", test::sci(lo.hemisphere));
  RecordProperty("cylinder_axis_deg_at_0.01", test::sci(lo.axis_deg));
  RecordProperty("sphere_origin_pct_at_0.1", test::sci(hi.sphere));
  RecordProperty("hemisphere_origin_pct_at_0.1", test::sci(hi.hemisphere));
  RecordProperty("cylinder_axis_deg_at_0.1", test::sci(hi.axis_deg));
  EXPECT_LT(hi.sphere, 0.3);
  EXPECT_LT(hi.hemisphere, 2.0);
  EXPECT_LT(hi.axis_deg, 0.2);
  EXPECT_LT(lo.sphere, 0.03);
  EXPECT_LT(lo.hemisphere, 0.2);
  EXPECT_LT(lo.axis_deg, 0.02);
  EXPECT_GT(hi.sphere, lo.sphere);  // the errors are the noise's, not a floor
  EXPECT_GT(hi.axis_deg, lo.axis_deg);
}

}  // namespace
}  // namespace polarform
