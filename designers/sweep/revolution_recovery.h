// Surface-of-revolution recovery from a point cloud or mesh vertices (Kantz 2003, §5.3, spec K11):
// the axis from the PCA frame's most distinct eigenvector (or the user's), refined on ring clusters
// or against the recovered profile by robust Gauss–Newton; every point projected to the meridian
// half-plane; the profile recovered and fitted to a tolerance; the exact surface of revolution
// (profile × rational quadratic circle, degree (2, p)); the true distances of all points.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "designers/sweep/recovery_steps.h"
#include "src/fit/principal_frame.h"
#include "src/fit/rotation_axis.h"

namespace polarform {

struct RevolutionOptions {
  std::optional<Eigen::Vector3d> axis_direction;  // given: no PCA start
  std::optional<Eigen::Vector3d> axis_point;      // given with the direction: a point on the axis
  bool refine_axis = true;
  double tolerance = 0.0;  // the max distance asked for; <= 0: 1e-4 of the size
  int degree = 3;
  double corner_angle = 0.5235987755982988;  // 30°
  int max_axis_points = 40000;  // the axis is refined on an evenly strided subset of this size
  int max_profile_axis_points = 12000;  // ... and of this size against a scan's profile
  // Scans: the (z, r) cell of the azimuthal coverage test, relative to the size
  // (azimuthal_coverage.h); points of one-sided cells are left out of the profile.
  double coverage_cell = 0.01;
  int threads = 2;
};

// SweptFit's profile is the meridian, its plane the (z, r) of every point, its surfaces of degree
// (2, p).
struct RevolutionRecovery : SweptFit {
  PrincipalFrame pca;
  double tie_ratio = 0.0;  // of the two eigenvalues other than the axis's
  AxisLine start_axis, axis;
  AxisRefinement refinement;  // rms before/after, iterations, covariance
  bool ring_axis = false;     // refined on ring clusters
  std::size_t set_aside = 0;  // scans: points left out of the profile (one-sided cells)
  struct Timings {
    double frame = 0, axis = 0, profile = 0, surface = 0, error = 0;
  } timings_s;
};

// Needs at least 8 finite points (InputError otherwise); NumericalError when no profile can be
// recovered.
RevolutionRecovery recover_revolution(const Eigen::Matrix3Xd& points,
                                      const RevolutionOptions& options = {});

// The exact surface of revolution of a (z, r) profile about the axis (NURBS Book A8.1).
NurbsSurface revolve_meridian(const NurbsCurve2d& profile, const AxisLine& axis);

}  // namespace polarform
