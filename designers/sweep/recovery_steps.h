// Helpers shared by the sweep recoveries (revolution, extrusion): the input checks, the seconds of
// a stage and an evenly strided subset of a cloud, on which a direction or an axis is estimated
// before every point is used for the profile and the errors. Kantz 2003, §5 works on a whole cloud;
// the subset only bounds the cost of the estimates.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <optional>
#include <string>

namespace polarform {

double seconds_since(std::chrono::steady_clock::time_point t0);

// Every k-th point, k the smallest stride that leaves at most max_points.
Eigen::Matrix3Xd strided(const Eigen::Matrix3Xd& points, int max_points);

// InputError "<what>: ..." for fewer than 8 points, a non-finite one or a zero direction.
void check_sweep_input(const Eigen::Matrix3Xd& points,
                       const std::optional<Eigen::Vector3d>& direction, const std::string& what);

}  // namespace polarform
