// The rounding unit of a cloud's coordinates: meshes carry vertices rounded to float32 (binary
// STL, float PLY) or to a few decimals (OBJ, ASCII STL, text clouds), which spreads a
// tessellation's rings by up to that unit; clusters and acceptance thresholds must stay above it.
#pragma once

#include <Eigen/Core>

namespace polarform {

// Half the unit in the last place of float32 at the largest coordinate magnitude when every
// coordinate is a float32 value; else half the decimal quantum 10^-d that 99 % of the
// coordinates (of an evenly strided subset of at most 30,000) are whole multiples of; at least
// half a double ulp of the largest magnitude.
double coordinate_rounding(const Eigen::Matrix3Xd& points);

}  // namespace polarform
