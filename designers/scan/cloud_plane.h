// The best-fit plane of a point cloud (total least squares: the normal is the eigenvector of the
// smallest eigenvalue of the scatter matrix) and a frame in it, which decides whether a scan is
// 2D (a profile: polar curve fitting, Bae 2002 ch. 2) and maps its points into plane coordinates.
// A plane within 1e-4 rad of z = const keeps the input's own x and y as its axes.
#pragma once

#include <Eigen/Core>
#include <optional>

#include "src/fit/local_frame.h"

namespace polarform {

struct CloudPlane {
  LocalFrame frame;           // origin on the plane, k = normal (k·z >= 0), i, j in the plane
  double rms_distance = 0.0;  // of the points from the plane
  double max_distance = 0.0;
  double size = 0.0;     // RMS distance of the points from their centroid, in the plane
  bool snapped = false;  // the plane is z = const and i, j are the input's x, y
  // The points lie in the plane within `relative` of their size (rms distance).
  bool planar(double relative = 1e-3) const { return rms_distance <= relative * size; }
};

// Throws InputError for fewer than 3 points, a non-finite point or a zero `normal`. A given
// normal fixes k (its sign kept); the origin is then the centroid projected along it.
CloudPlane fit_plane(const Eigen::Matrix3Xd& points,
                     const std::optional<Eigen::Vector3d>& normal = {});

}  // namespace polarform
