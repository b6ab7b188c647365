// The profile curves of a band of 2D points (Kantz 2003, §4.5 "slicing algorithm", spec K7): either
// ring clusters (a mesh whose vertices lie on exact circles collapses into a few exact points; they
// are merged, ordered by the shortest tour and cut where it runs along the axis or returns along
// one edge over 3× longer than any other) or a scan band (MLS thinning, ordered subset
// selection); then corners and the parametric least-squares fit to a
// tolerance (spec B1). Profile ends on the axis (r = 0) are interpolated exactly there (poles).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "src/nurbs/nurbs_curve.h"

namespace polarform {

struct MeridianOptions {
  double tolerance = 0.0;  // max distance of the profile points to the curve; <= 0: 1e-4·size
  int degree = 3;
  double corner_angle = 0.5235987755982988;  // 30°
  // Ring cluster radius; <= 0: max(1e-7·size, 1e-2·tolerance, 8·rounding), above the spread the
  // coordinates' rounding (coordinate_rounding.h) gives a ring.
  double merge = 0.0;
  double rounding = 0.0;
  bool axis_ends = true;        // open ends within the snap distance of r = 0 go to r = 0 exactly
  int max_structure_points = 4000;  // scan bands are thinned and ordered on a strided subset
  int max_scan_points = 60000;      // ... and the profile refitted on one of this size
  int threads = 2;
};

struct MeridianLoop {
  NurbsCurve2d curve;  // (z, r), domain [0, 1]
  bool closed = false;
  Eigen::Matrix2Xd points;  // the ordered profile points it was fitted to
  std::vector<Eigen::Vector2d> corners;
  bool start_on_axis = false, end_on_axis = false;
  double fit_max = 0.0;  // max distance of `points` to the curve
  bool tolerance_met = false;
};

struct MeridianProfile {
  std::vector<MeridianLoop> loops;
  bool rings = false;      // built from ring clusters
  int clusters = 0;        // ring clusters (rings) or thinned points (scans)
  double size = 0.0;       // diagonal of the band's bounding box
  double spacing = 0.0;    // scans: median nearest-neighbour distance of the subset
  double tolerance = 0.0;  // the tolerance used
};

// Throws InputError for fewer than 4 points or non-finite ones; NumericalError when no profile
// can be ordered out of the band.
MeridianProfile recover_meridian_profile(const Eigen::Matrix2Xd& zr,
                                         const MeridianOptions& options);

// Signed distances of points to the profile (the nearest loop), sign by the curve's left normal,
// with the unit normal at the foot; for the axis refinement and the error report. Parallel.
struct MeridianDistances {
  Eigen::VectorXd distance;
  Eigen::Matrix2Xd normal;
  std::vector<int> loop;
};
MeridianDistances meridian_distances(const MeridianProfile& profile, const Eigen::Matrix2Xd& zr,
                                     int threads = 2);

}  // namespace polarform
