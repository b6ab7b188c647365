// The separate contours of a 2D profile scan, for the message of a polar fit that is refused: a
// cam with its bore, or a plate with a hole, is two closed loops, which no r = F(θ) about one
// centre can follow. Points closer than 16 times the 90th percentile of their nearest-neighbour
// distances are linked (single linkage: connected components by union–find); a contour is a loop
// when it goes around the centre, or around a centre of its own, with no angular gap over 90°.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

namespace polarform {

struct ProfileContour {
  std::size_t points = 0;
  bool loop = false;           // closed: around the centre, or around a centre of its own
  bool around_centre = false;  // its points surround the origin
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // the origin, or its own (circle fit)
  double radius = 0.0;                               // median distance of its points from `centre`
};

// The contours of points (2D, the polar centre at the origin) with at least max(12, 1 % of the
// points) each, largest first.
std::vector<ProfileContour> profile_contours(const Eigen::Matrix2Xd& points);

// "two loops found (radii about 40 mm and 12 mm around the centre): use scan-cam, or remove the
// inner loop" when at least two of the contours are loops; a loop off the centre reads "radius
// about 8 mm around (x, y)" (`offset` added: the polar centre in the caller's coordinates). Empty
// when fewer than two are loops.
std::string describe_loops(const std::vector<ProfileContour>& contours,
                           const Eigen::Vector2d& offset);

}  // namespace polarform
