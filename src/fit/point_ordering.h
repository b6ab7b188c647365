// Ordering a thin 2D band into polylines and loops (Kantz 2003, §4.1; Lee 2000, ordered subset
// selection): from a start point, the neighbours within a radius are split by the local regression
// line into the two sides, the farthest of each side is kept and the rest is dropped; the walk goes
// on from the kept points until nothing is left. Further chains start from the nearest unvisited
// point; a chain whose ends are within 2r closes into a loop (spec K6).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace polarform {

struct OrderedChain {
  std::vector<int> nodes;   // the kept points, in order along the chain
  std::vector<int> points;  // every point the chain took (nodes and dropped ones), in order
  bool closed = false;
};

// Chains of at least min_points points (others are dropped as stray), longest first. Points must be
// finite; radius > 0.
std::vector<OrderedChain> order_points(const Eigen::Matrix2Xd& points, double radius,
                                       int min_points = 8);

}  // namespace polarform
