// Corners of an ordered point sequence (spec B1, "corner detection", for Kantz 2003 profiles): the
// turning angle at point i between the total-least-squares directions of the k points before and
// the k points after it; a corner is an angle above a threshold that is the largest within k
// points.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace polarform {

// Indices of the corners of the ordered columns of `points` (2D or 3D), increasing. `closed`
// wraps the neighbourhoods around the ends; open curves have no corner at their first and last
// point. k >= 1 (k = 1: the angle between the two edges at a polyline vertex).
template <int Dim>
std::vector<int> detect_corners(const Eigen::Matrix<double, Dim, Eigen::Dynamic>& points,
                                bool closed, double corner_angle, int k);

// The turning angle (radians, in [0, π]) at every point, as detect_corners measures it; 0 where
// a side has no points.
template <int Dim>
Eigen::VectorXd turning_angles(const Eigen::Matrix<double, Dim, Eigen::Dynamic>& points,
                               bool closed, int k);

}  // namespace polarform
