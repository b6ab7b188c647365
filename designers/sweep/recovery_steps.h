// What the sweep recoveries (revolution, extrusion) share: the result common to both and the
// helpers — the input checks, the seconds of a stage and an evenly strided subset of a cloud, on
// which a direction or an axis is estimated before every point is used for the profile and the
// errors. Kantz 2003, §5 works on a whole cloud; the subset only bounds the cost of the estimates.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "designers/sweep/meridian_profile.h"
#include "src/fit/error_stats.h"
#include "src/nurbs/nurbs_surface.h"

namespace polarform {

// A recovered sweep (Kantz 2003, §5): the profile in its plane — the meridian (z, r) of a surface
// of revolution, the section (x, y) of an extrusion — every point's coordinates in that plane,
// the exact swept surfaces (one per profile loop) and the true distances of all points.
struct SweptFit {
  MeridianProfile profile;
  std::vector<NurbsSurface> surfaces;
  Eigen::Matrix2Xd plane;     // the profile-plane coordinates of every point
  Eigen::VectorXd distances;  // signed true distances of every point to the surfaces
  ErrorStats error;
  double size = 0.0;  // bounding-box diagonal of the points
  double tolerance = 0.0;
  std::size_t unexplained = 0;  // points farther than the tolerance
};

// Fills fit.distances, error and unexplained: the signed distances of the plane coordinates to the
// profile's curves, which are the true 3D distances for a surface of revolution and for an
// extrusion (every point within its extent) alike.
void measure_point_errors(SweptFit& fit, int threads);

double seconds_since(std::chrono::steady_clock::time_point t0);

// The columns whose flag is non-zero (all of them when flags is empty).
Eigen::Matrix2Xd kept_columns(const Eigen::Matrix2Xd& points, const std::vector<char>& flags);

// Every k-th point, k the smallest stride that leaves at most max_points.
Eigen::Matrix3Xd strided(const Eigen::Matrix3Xd& points, int max_points);

// InputError "<what>: ..." for fewer than 8 points, a non-finite one or a zero direction.
void check_sweep_input(const Eigen::Matrix3Xd& points,
                       const std::optional<Eigen::Vector3d>& direction, const std::string& what);

}  // namespace polarform
