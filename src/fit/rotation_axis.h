// The rotation axis of a surface of revolution (Kantz 2003, §5.3 and its "future work", done as
// spec K11 step 4): points go to meridian coordinates (z along the axis, r from it), and the four
// axis parameters (two direction angles, a 2D offset ⟂ the axis) are refined by robust
// Gauss–Newton (Tukey IRLS), either against a profile model supplied by the caller (distances of
// (z, r) to the meridian curve) or, for meshes whose vertices lie on rings, against the spread of
// each ring's (z, r) cluster, which is zero only for the exact axis.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <utility>

namespace polarform {

struct AxisLine {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit
};

// Two unit vectors e1, e2 completing the unit direction a to a right-handed frame (e1 × e2 = a).
std::pair<Eigen::Vector3d, Eigen::Vector3d> normal_pair(const Eigen::Vector3d& a);

// (z, r) per point: z = a·(p − c), r = |(p − c) − z a| (spec K11 step 2). Parallel over `threads`.
Eigen::Matrix2Xd meridian_coordinates(const Eigen::Matrix3Xd& points, const AxisLine& axis,
                                      int threads = 1);

// What a profile model says about meridian points: signed distance d_k to the meridian curve and
// the curve's unit normal n_k at the foot (∂d/∂(z, r)); `valid` false for points without a foot.
struct MeridianResiduals {
  Eigen::VectorXd distance;
  Eigen::Matrix2Xd normal;
  std::vector<char> valid;
};
using MeridianModel = std::function<MeridianResiduals(const Eigen::Matrix2Xd& zr)>;

struct AxisRefinementOptions {
  int max_iterations = 30;
  double step_tolerance = 1e-10;  // relative to `size`: stop when the axis moves less
  double size = 1.0;              // the object's size (box diagonal)
  double scale_floor = 0.0;       // lower bound of the robust scale (e.g. the tolerance / 3)
  int threads = 2;
  // A direction or a point the user gave: the direction is kept (only the line's offset is
  // refined), or the line keeps passing through the start point (only the direction is refined).
  bool fix_direction = false, fix_point = false;
};

struct AxisRefinement {
  AxisLine axis;
  double rms_before = 0.0, rms_after = 0.0;  // of the (weighted-in) residuals
  int iterations = 0;
  bool converged = false;
  double clustered = 0.0;  // rings: the fraction of the points in clusters at the last iteration
  // Covariance of the last step's 4 parameters (angles in rad, offsets in mm) under the residual
  // scale: σ²(JᵀWJ)⁻¹, the axis uncertainty a noisy scan leaves.
  Eigen::Matrix4d covariance = Eigen::Matrix4d::Zero();
};

// Gauss–Newton against a profile model that is refitted every iteration (alternating), Tukey
// biweights on the scale 1.4826·MAD (at least scale_floor).
AxisRefinement refine_axis_by_profile(const Eigen::Matrix3Xd& points, const AxisLine& start,
                                      const MeridianModel& model,
                                      const AxisRefinementOptions& options);

// Gauss–Newton on the ring clusters: points whose (z, r) lie within `merge` of each other form a
// cluster (single linkage); residual (z_k, r_k) − cluster mean, both components. The merge radius
// shrinks to 10× the median remaining spread as the axis converges. Clusters of fewer than 3 points
// are ignored. Returns converged = false when fewer than 2 clusters are found.
AxisRefinement refine_axis_by_rings(const Eigen::Matrix3Xd& points, const AxisLine& start,
                                    double merge, const AxisRefinementOptions& options);

// Cluster labels of 2D points by single linkage within `merge` (grid index; points within
// 1e-3·merge of an expanded one are not expanded themselves), -1 for clusters with fewer than
// min_size points; returns the number of clusters kept.
int cluster_points(const Eigen::Matrix2Xd& points, double merge, int min_size,
                   std::vector<int>& label);

}  // namespace polarform
