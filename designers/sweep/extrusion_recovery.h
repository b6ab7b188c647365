// Extrusion (linear translational sweep) recovery from a point cloud or mesh vertices (Kantz
// 2003, §5.2.1, spec K10): the direction from the local surface normals (the direction most
// perpendicular to them), refined against the section (extrusion_direction.h); every point
// projected along it onto the section plane; the section loops fitted to a tolerance; the extent;
// the exact extruded surfaces (degree (p, 1)); the true distances of all points.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "designers/sweep/extrusion_direction.h"
#include "designers/sweep/recovery_steps.h"
#include "src/fit/principal_frame.h"

namespace polarform {

struct ExtrusionOptions {
  std::optional<Eigen::Vector3d> direction;  // given: the start of the refinement
  bool refine_direction = true;
  double tolerance = 0.0;                    // the max distance asked for; <= 0: 1e-4 of the size
  int degree = 3;
  double corner_angle = 0.5235987755982988;  // 30°
  int normal_neighbours = 16;                // local PCA of this many nearest points
  int max_direction_points = 20000;  // the direction is estimated on an evenly strided subset
  int max_refine_points = 8000;      // ... and refined on one of this size
  int threads = 2;
};

// SweptFit's profile is the section in (e1, e2) coordinates, its plane the projection of every
// point, its surfaces of degree (p, 1).
struct ExtrusionRecovery : SweptFit {
  PrincipalFrame pca;
  Eigen::Vector3d start_direction = Eigen::Vector3d::UnitZ();  // from the normals (or given)
  double normals_flatness = 0.0;  // λ_min / Σλ of Σ n nᵀ: 0 when every normal is ⟂ a direction
  DirectionRefinement refinement;
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // refined, unit
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // the centroid: section plane origin, v = 0
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX(), e2 = Eigen::Vector3d::UnitY();  // e1 × e2 = d
  double v_low = 0.0, v_high = 0.0;  // extent along the direction from the origin
  double length() const { return v_high - v_low; }
  struct Timings {
    double frame = 0, direction = 0, profile = 0, surface = 0, error = 0;
  } timings_s;
};

// Needs at least 8 finite points (InputError otherwise); NumericalError when no section can be
// recovered.
ExtrusionRecovery recover_extrusion(const Eigen::Matrix3Xd& points,
                                    const ExtrusionOptions& options = {});

// The direction most perpendicular to the surface normals (src/fit/local_normals.h): the smallest
// eigenvector of Σ n nᵀ, sign ⟨d, hint⟩ >= 0; and how flat the normals are: λ_min / Σλ, 0 for an
// extrusion, 1/3 for a sphere.
struct NormalsDirection {
  Eigen::Vector3d direction;
  double flatness = 0.0;
};
NormalsDirection normals_direction(const Eigen::Matrix3Xd& normals, const Eigen::Vector3d& hint);

}  // namespace polarform
