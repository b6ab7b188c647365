// Which points of a scan a surface of revolution can explain (issue 18: a non-rotational feature,
// such as a handle, must not tilt the axis): in the meridian half-plane, a cell of a rotational
// surface holds points from all around the axis (as far as the scan reaches), while a feature on
// one side fills its cells from a narrow range of azimuths. Each (z, r) cell's distinct azimuth
// sectors are compared with the number its point count would cover at random (S(1 − (1 − 1/S)^c));
// points in cells whose ratio is below half the median ratio (over points) are set aside.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/fit/rotation_axis.h"

namespace polarform {

struct AzimuthalCoverage {
  std::vector<char> rotational;  // per point: 1 where the cell's azimuths cover the circle
  std::size_t set_aside = 0;     // points with 0
  double median_ratio = 0.0;
};

// cell: the (z, r) cell size [mm]; sectors: azimuth sectors of the circle.
AzimuthalCoverage azimuthal_coverage(const Eigen::Matrix3Xd& points, const AxisLine& axis,
                                     double cell, int sectors = 16);

}  // namespace polarform
