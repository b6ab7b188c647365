// Helpers shared by the sweep recoveries (revolution, extrusion): the input checks, the seconds of
// a stage and an evenly strided subset of a cloud, on which a direction or an axis is estimated
// before every point is used for the profile and the errors. Kantz 2003, §5 works on a whole cloud;
// the subset only bounds the cost of the estimates.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <cstddef>
#include <optional>
#include <string>

#include "designers/sweep/meridian_profile.h"
#include "src/fit/error_stats.h"

namespace polarform {

// The errors of every point: signed distances of its plane coordinates to the profile's curves
// (the true 3D distances for a surface of revolution and an extrusion alike), their statistics
// and the count beyond the tolerance.
struct PointErrors {
  Eigen::VectorXd distances;
  ErrorStats error;
  std::size_t unexplained = 0;
};
PointErrors point_errors(const MeridianProfile& profile, const Eigen::Matrix2Xd& plane_points,
                         double tolerance, int threads);

double seconds_since(std::chrono::steady_clock::time_point t0);

// Every k-th point, k the smallest stride that leaves at most max_points.
Eigen::Matrix3Xd strided(const Eigen::Matrix3Xd& points, int max_points);

// InputError "<what>: ..." for fewer than 8 points, a non-finite one or a zero direction.
void check_sweep_input(const Eigen::Matrix3Xd& points,
                       const std::optional<Eigen::Vector3d>& direction, const std::string& what);

}  // namespace polarform
