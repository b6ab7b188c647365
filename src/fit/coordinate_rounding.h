// The rounding unit of a cloud's coordinates: meshes stored in single precision (binary STL,
// float PLY) carry vertices rounded to float32, which spreads a tessellation's rings by about
// 1e-7 of the largest coordinate; clusters and acceptance thresholds must stay above it.
#pragma once

#include <Eigen/Core>

namespace polarform {

// Half the unit in the last place, at the largest coordinate magnitude, of float32 when every
// coordinate is a float32 value, else of double.
double coordinate_rounding(const Eigen::Matrix3Xd& points);

}  // namespace polarform
