// Candidate local frames for the surface fits besides the quadric frame (Bae 2002, §4.3): a
// least-squares axis line for cylinder-like data (Gauss–Newton on the distance-to-axis residual of
// a surface of revolution r(t) = c0 + c1 t + c2 t², t along the axis) and a least-squares centre
// for sphere-like data (Gauss–Newton on |p − c| − R). Each candidate is a name, an origin, an axis
// and how it was found; the fitter scores it by the error its fit achieves (rotational_fit.h).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace polarform {

struct FrameCandidate {
  std::string
      name;  // "quadric", "least-squares axis", "least-squares centre" (a PCA frame: one more)
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  std::string how;      // how it was found, with its residual
  double rms = -1.0;    // the fit's rms true distance with this frame (< 0: not fitted)
  std::string failure;  // why its fit failed (not single-valued, …), empty when it did not
  // Filled by the fitter: whether F(u) alone explained the data in this frame (the F-test of
  // revolution_test.h), and the fit's size.
  bool rotational = false;
  double p_value = -1.0;   // of the F-test (< 0: not tested)
  long coefficients = 0;   // of F
  std::size_t points = 0;  // the error statistics' count
};

// A start of the profile refinement: a name and a line.
struct AxisStart {
  std::string name;
  Eigen::Vector3d origin, axis;
};

// The line (origin on it, unit axis) minimising Σ (dist(p, line) − r(t))², r quadratic in t, by
// Gauss–Newton from the start line; a given origin or axis stays fixed (the other is refined).
// At most 20,000 evenly strided points are used.
FrameCandidate least_squares_axis(const Eigen::Matrix3Xd& points,
                                  const Eigen::Vector3d& start_origin,
                                  const Eigen::Vector3d& start_axis, bool fix_origin,
                                  bool fix_axis);

// The centre minimising Σ (|p − c| − R)² by Gauss–Newton from the start centre (the axis is kept).
FrameCandidate least_squares_centre(const Eigen::Matrix3Xd& points,
                                    const Eigen::Vector3d& start_centre,
                                    const Eigen::Vector3d& axis);

// What the user gave of the axis line: a point on it (a centre) or its direction.
struct AxisConstraint {
  std::optional<Eigen::Vector3d> point, direction;
};

// The axis of a surface of revolution by the rotational criterion (Kantz 2003, §5.3; spec K11
// step 4): from the PCA axis (the most distinct eigenvector through the centroid) and from each of
// `starts`, refine_axis_by_profile against a meridian profile whose size GCV chooses at the start
// and again at the refined axis (a second pass); the start whose refinement ends with the smallest
// robust rms residual wins; the other two principal axes start too where a profile about them
// misses by at most twice the best start's (on a partial scan the most distinct eigenvalue can
// belong to a transverse axis). A given point or direction is kept: every start is moved through
// the point (its direction refined) or turned to the direction (its offset refined). At most 50,000
// evenly strided points are used. Named "PCA + profile refinement"; `how` lists every start with
// its residual.
FrameCandidate profile_refined_axis(const Eigen::Matrix3Xd& points,
                                    const std::vector<AxisStart>& starts = {},
                                    const AxisConstraint& given = {});

}  // namespace polarform
