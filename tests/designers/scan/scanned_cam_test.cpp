// The scanned-cam pipeline (designers/scan) on synthetic scans of designed cams with known
// displacement: the follower motion, the base radius and the phase are recovered within stated
// bounds from 2D profile scans and 3D plate scans, with and without a nominal design.
#include "designers/scan/scanned_cam.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "designers/cam/cam_design.h"
#include "designers/scan/nominal_comparison.h"
#include "src/error.h"
#include "src/units.h"
#include "tests/support/designers/example_cams.h"
#include "tests/support/designers/synthetic_scans.h"

namespace polarform {
namespace {

constexpr double kPi = std::numbers::pi;

PlateCam example_cam(const std::string& name) {
  return make_plate_cam(test::example_cam_design(name));
}

// max |s_recovered(θ) − s_nominal(θ)| over a dense grid of cam angles.
double max_displacement_error(const ScannedCam& scan, const PlateCam& cam) {
  double worst = 0.0;
  for (int i = 0; i < 3600; ++i) {
    const double theta = 2 * kPi * i / 3600;
    double s[4], n[4];
    scan.displacement_derivatives(theta, 0, s);
    cam.program().derivatives(theta, 0, n);
    worst = std::max(worst, std::abs(s[0] - n[0]));
  }
  return worst;
}

TEST(ScannedCam, RollerProfileScanWithNominalRecoversPhaseAndMotion) {
  const PlateCam cam = example_cam("roller");
  CamScanSetup setup;
  setup.centre = Eigen::Vector2d(12.5, -7.25);
  setup.phase = 30.0 / kDegreesPerRadian;
  setup.sigma = 0.005;
  const Eigen::Matrix3Xd points = cam_profile_scan(cam, setup);
  ScannedCamOptions o;
  o.follower = cam.follower();
  o.rotation = cam.rotation();
  o.nominal = cam;
  const ScannedCam scan = analyse_scanned_cam(points, o);
  ASSERT_TRUE(scan.alignment);
  EXPECT_FALSE(scan.mirrored);
  EXPECT_NEAR(scan.alignment->phase * kDegreesPerRadian, 30.0, 0.01);
  EXPECT_NEAR(scan.cam_frame.origin.x(), 12.5, 2e-3);
  EXPECT_NEAR(scan.cam_frame.origin.y(), -7.25, 2e-3);
  // The noise floor is stated close to the σ put in.
  EXPECT_NEAR(scan.contour_noise, 0.005, 0.0005);
  EXPECT_NEAR(scan.displacement.noise, 0.005, 0.0005);
  EXPECT_LT(scan.displacement.standard_error, 0.002);
  const double s_error = max_displacement_error(scan, cam);
  EXPECT_LT(s_error, 0.005);  // max |Δs| below σ with 3600 samples
  EXPECT_NEAR(scan.base_radius, cam.base_radius(), 0.005);
  const NominalComparison c = compare_to_nominal(scan, cam);
  EXPECT_LT(c.normal_stats.rms, 0.002);
  EXPECT_LT(c.normal_stats.max, 0.006);
  EXPECT_NEAR(c.point_stats.rms, 0.005, 0.0006);  // the scanned points scatter by σ about nominal
  RecordProperty("phase_error_deg",
                 std::to_string(scan.alignment->phase * kDegreesPerRadian - 30.0));
  RecordProperty("max_s_error_mm", std::to_string(s_error));
}

TEST(ScannedCam, MirroredScanIsDetected) {
  const PlateCam cam = example_cam("offset_roller");
  CamScanSetup setup;
  setup.phase = 200.0 / kDegreesPerRadian;
  setup.sigma = 0.002;
  Eigen::Matrix3Xd points = cam_profile_scan(cam, setup);
  points.row(1) *= -1.0;  // seen from the other face
  ScannedCamOptions o;
  o.follower = cam.follower();
  o.rotation = cam.rotation();
  o.nominal = cam;
  const ScannedCam scan = analyse_scanned_cam(points, o);
  EXPECT_TRUE(scan.mirrored);
  EXPECT_LT(max_displacement_error(scan, cam), 0.003);
  EXPECT_NEAR(scan.cam_frame.axes.determinant(), 1.0, 1e-12);
}

TEST(ScannedCam, FlatFacedProfileWithoutNominalRecoversMotionAndBaseRadius) {
  const PlateCam cam = example_cam("flat_faced");
  CamScanSetup setup;  // the cam frame is the scan's: no phase, centre at the origin
  setup.sigma = 0.003;
  const Eigen::Matrix3Xd points = cam_profile_scan(cam, setup);
  ScannedCamOptions o;
  o.follower = cam.follower();
  o.rotation = cam.rotation();
  const ScannedCam scan = analyse_scanned_cam(points, o);
  EXPECT_FALSE(scan.alignment);
  const double s_error = max_displacement_error(scan, cam);
  EXPECT_LT(s_error, 0.004);
  EXPECT_NEAR(scan.base_radius, cam.base_radius(), 0.004);
  RecordProperty("max_s_error_mm", std::to_string(s_error));
}

TEST(ScannedCam, ThreeDimensionalPlateScanFindsAxisFacesAndMotion) {
  const PlateCam cam = example_cam("roller");
  CamScanSetup setup;
  setup.phase = 75.0 / kDegreesPerRadian;
  setup.sigma = 0.004;
  setup.contour_points = 4000;
  RigidMotion placement;
  placement.rotation =
      Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 0.5).normalized()).toRotationMatrix();
  placement.translation = Eigen::Vector3d(40, -20, 15);
  const Eigen::Matrix3Xd points = cam_solid_scan(cam, setup, 12.0, 3000, placement);
  ScannedCamOptions o;
  o.follower = cam.follower();
  o.rotation = cam.rotation();
  o.nominal = cam;
  const ScannedCam scan = analyse_scanned_cam(points, o);
  EXPECT_TRUE(scan.profile.three_d);
  EXPECT_NEAR(std::abs(scan.profile.thickness), 12.0, 0.01);
  const Eigen::Vector3d axis = placement.rotation.col(2);
  EXPECT_GT(std::abs(scan.cam_frame.axes.col(2).dot(axis)), std::cos(1e-3));
  EXPECT_LT((scan.cam_frame.origin - placement.translation).norm(), 0.01);
  // The cam frame in scan coordinates is the placement of the design turned by the phase.
  const Eigen::Matrix3d truth =
      placement.rotation * Eigen::AngleAxisd(75.0 / kDegreesPerRadian, Eigen::Vector3d::UnitZ());
  const double frame_angle = std::acos(std::min(1.0, scan.cam_frame.axes.col(0).dot(truth.col(0))));
  EXPECT_LT(frame_angle * kDegreesPerRadian, 0.02);
  RecordProperty("cam_frame_angle_error_deg", std::to_string(frame_angle * kDegreesPerRadian));
  const double s_error = max_displacement_error(scan, cam);
  EXPECT_LT(s_error, 0.006);
  RecordProperty("max_s_error_mm", std::to_string(s_error));
}

TEST(ScannedCam, RefusesAScanWithoutBoreOrCentre) {
  const PlateCam cam = example_cam("roller");
  CamScanSetup setup;
  setup.bore_points = 0;
  const Eigen::Matrix3Xd points = cam_profile_scan(cam, setup);
  ScannedCamOptions o;
  o.follower = cam.follower();
  try {
    analyse_scanned_cam(points, o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no bore found"), std::string::npos) << e.what();
  }
  o.profile.centre = Eigen::Vector3d::Zero();  // with the centre given it works
  EXPECT_LT(max_displacement_error(analyse_scanned_cam(points, o), cam), 0.005);
}

TEST(ScannedCam, RefusesTooFewPoints) {
  ScannedCamOptions o;
  EXPECT_THROW(analyse_scanned_cam(Eigen::Matrix3Xd::Random(3, 10), o), InputError);
}

}  // namespace
}  // namespace polarform
