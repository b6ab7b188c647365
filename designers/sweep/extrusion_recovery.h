// Extrusion (linear translational sweep) recovery from a point cloud or mesh vertices (Kantz
// 2003, §5.2.1, spec K10): the direction from the local surface normals (the direction most
// perpendicular to them; not refined against the section yet); every point
// projected along it onto the section plane; the section loops fitted to a tolerance; the extent;
// the exact extruded surfaces (degree (p, 1)); the true distances of all points.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "designers/sweep/meridian_profile.h"
#include "src/fit/error_stats.h"
#include "src/fit/principal_frame.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

struct ExtrusionOptions {
  std::optional<Eigen::Vector3d> direction;  // given: used as is
  double tolerance = 0.0;                    // the max distance asked for; <= 0: 1e-4 of the size
  int degree = 3;
  double corner_angle = 0.5235987755982988;  // 30°
  int normal_neighbours = 16;                // local PCA of this many nearest points
  int max_direction_points = 20000;  // the direction is estimated on an evenly strided subset
  int threads = 2;
};

struct ExtrusionRecovery {
  PrincipalFrame pca;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // from the normals (or given), unit
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // the centroid: section plane origin, v = 0
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX(), e2 = Eigen::Vector3d::UnitY();  // e1 × e2 = d
  double v_low = 0.0, v_high = 0.0;  // extent along the direction from the origin
  double length() const { return v_high - v_low; }
  MeridianProfile section;             // loops in (e1, e2) coordinates
  std::vector<NurbsSurface> surfaces;  // one per loop, degree (p, 1)
  Eigen::Matrix2Xd projected;          // (e1, e2) coordinates of every point
  Eigen::VectorXd distances;           // signed true distances of every point
  ErrorStats error;
  double size = 0.0;  // bounding-box diagonal of the points
  double tolerance = 0.0;
  std::size_t unexplained = 0;  // points farther than the tolerance
  struct Timings {
    double frame = 0, direction = 0, profile = 0, surface = 0, error = 0;
  } timings_s;
};

// Needs at least 8 finite points (InputError otherwise); NumericalError when no section can be
// recovered.
ExtrusionRecovery recover_extrusion(const Eigen::Matrix3Xd& points,
                                    const ExtrusionOptions& options = {});

// The direction most perpendicular to the local surface normals: the smallest eigenvector of
// Σ n nᵀ, normals from the local PCA of the k nearest points (Hoppe et al. 1992). Sign: ⟨d, hint⟩
// >= 0.
Eigen::Vector3d normals_direction(const Eigen::Matrix3Xd& points, int neighbours,
                                  const Eigen::Vector3d& hint, int threads = 2);

}  // namespace polarform
