// Synthetic scans with known answers for the tests of the scan pipeline and the fit jobs (the
// bundled examples/scans are made by scripts/make-example-scans.py): clouds sampled from analytic
// rotational shapes (a cylinder-like vase, a true sphere, a true cone) and from a designed plate
// cam (a 2D profile scan with its bore, a 3D scan of both faces, the side and the bore), with
// stated Gaussian noise and a known placement.
// Deterministic for a seed (std::mt19937 and its normal distribution).
#pragma once

#include <Eigen/Core>

#include "designers/cam/plate_cam.h"

namespace polarform {

// x ↦ R·x + t.
struct RigidMotion {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Matrix3Xd operator()(const Eigen::Matrix3Xd& x) const;
};

// A waisted vase r(z, θ) = 24 − 5 sin(π z / 80) + 0.8 cos 2θ · z / 80 mm over z ∈ [0, 80],
// uniform in (z, θ), isotropic noise σ.
double vase_radius(double z, double theta);
Eigen::Matrix3Xd vase_cloud(int n, double sigma, unsigned seed);

// Exact points (no noise) on the sphere |x − centre| = radius, area-uniform.
Eigen::Matrix3Xd sphere_cloud(int n, double radius, const Eigen::Vector3d& centre, unsigned seed);

// Exact points on the cone frustum r = r0 + slope·z about the z axis, z ∈ [0, height].
Eigen::Matrix3Xd cone_cloud(int n, double r0, double slope, double height, unsigned seed);

// Where and how a cam is scanned: its centre in the scan, the angle it is turned by about its
// axis (counter-clockwise, rad) relative to the design's cam frame, the bore, and the noise.
struct CamScanSetup {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  double phase = 0.0;
  double bore_radius = 8.0;
  double sigma = 0.005;  // 2D: along the contour normal; 3D: per coordinate
  int contour_points = 3600;
  int bore_points = 400;
  unsigned seed = 1;
};

// A 2D profile scan (z = 0): contour points at uniformly random cam angles, moved along the
// contour normal by N(0, σ), and bore points on the circle of bore_radius about the centre.
Eigen::Matrix3Xd cam_profile_scan(const PlateCam& cam, const CamScanSetup& setup);

// A 3D scan of the cam as a plate of `thickness` between z = ±thickness/2 in the cam frame
// (turned by setup.phase, centred at setup.centre): `face_points` on each face between the bore
// and the contour, setup.contour_points on the side, setup.bore_points on the bore wall, with
// isotropic noise σ, then moved by `placement`.
Eigen::Matrix3Xd cam_solid_scan(const PlateCam& cam, const CamScanSetup& setup, double thickness,
                                int face_points, const RigidMotion& placement);

}  // namespace polarform
