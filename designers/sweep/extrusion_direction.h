// The extrusion direction refined against the section (Kantz 2003, §5.2.1, the direction
// "refined"; the extrusion counterpart of rotation_axis.h's profile refinement): every point is
// projected along d onto the plane ⟂ d, a section model is fitted to the projection, and the two
// tilt angles of d move by robust Gauss–Newton on the signed distances to it (Tukey biweights on
// 1.4826·MAD, at least the scale floor), the model refitted every iteration.
#pragma once

#include <Eigen/Core>

#include "src/fit/rotation_axis.h"

namespace polarform {

// (e1·(p − c), e2·(p − c)) of every point: the projection along e1 × e2 onto the plane through c.
Eigen::Matrix2Xd project_onto_plane(const Eigen::Matrix3Xd& points, const Eigen::Vector3d& c,
                                    const Eigen::Vector3d& e1, const Eigen::Vector3d& e2);

struct DirectionRefinement {
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit, the start's sense
  double rms_before = 0.0, rms_after = 0.0;              // of the weighted-in section residuals
  int iterations = 0;
  bool converged = false;
  // σ²(JᵀWJ)⁻¹ of the last step's two tilt angles [rad²]: the uncertainty the noise leaves.
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
};

// Gauss–Newton on Σ w_k d_k², d_k the model's signed distance of point k's projection, with
// ∂d_k/∂(a, b) = h_k (n_k,2, −n_k,1) for the frame turned by a e1 + b e2 (h_k the height along d,
// n_k the model's unit normal); each tilt step at most 0.05 rad. `origin` is the plane's point;
// the options' size, step_tolerance, max_iterations, scale_floor and threads apply.
DirectionRefinement refine_extrusion_direction(const Eigen::Matrix3Xd& points,
                                               const Eigen::Vector3d& origin,
                                               const Eigen::Vector3d& start,
                                               const MeridianModel& model,
                                               const AxisRefinementOptions& options);

}  // namespace polarform
