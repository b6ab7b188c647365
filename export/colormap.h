// Colour maps for values on points and control nets: a diverging blue–white–red map for signed
// deviations (symmetric about zero) and a sequential map for scalar fields (viridis, van der Walt
// & Smith 2015, by linear interpolation of 9 anchor colours). Colours are RGB in [0, 1].
#pragma once

#include <Eigen/Core>
#include <array>

namespace polarform {

// d / limit clamped to [-1, 1]: -1 blue, 0 white, +1 red. limit > 0.
Eigen::Vector3d diverging_color(double d, double limit);

// (v − lo) / (hi − lo) clamped to [0, 1] along viridis; hi == lo gives the middle colour.
Eigen::Vector3d sequential_color(double v, double lo, double hi);

// The colour as 8-bit RGB.
std::array<unsigned char, 3> to_rgb8(const Eigen::Vector3d& c);

}  // namespace polarform
