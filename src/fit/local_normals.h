// Unoriented surface normals of a point cloud by local PCA (Hoppe et al. 1992): each point's
// normal is the least-variance direction of its k nearest points.
#pragma once

#include <Eigen/Core>

namespace polarform {

// One unit normal per point (sign arbitrary); zero where fewer than 3 neighbours exist. Parallel.
Eigen::Matrix3Xd local_normals(const Eigen::Matrix3Xd& points, int neighbours, int threads = 2);

}  // namespace polarform
