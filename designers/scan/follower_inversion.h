// Follower inversion for a scanned plate cam: every contour point of the scan, in the cam frame,
// tells at which cam angle θ it meets the follower and how high the follower then stands on its
// line (y0 + s(θ)), in the conventions of designers/cam (follower axis ∥ +y through x = e, the cam
// turned by σθ, plate_cam.h). The contour normal comes from the fitted profile at the point's foot
// (profile_foot.h). Knife-edge: the point itself is the pitch point; roller: the pitch point is
// the point moved Rr along the outward normal (the pitch curve is the contour's offset); flat face:
// the face touches where the contour normal is +y, at the height of the support function c·n.
#pragma once

#include <Eigen/Core>

#include "designers/cam/plate_cam.h"
#include "src/fit/polar_curve_fit.h"

namespace polarform {

struct FollowerSamples {
  Eigen::VectorXd theta;   // cam angle in [0, 2π), rad
  Eigen::VectorXd height;  // y0 + s(θ) along the follower line, mm
};

// points: contour points in the cam frame (centre at the origin); contour: the fitted profile in
// the same frame. Throws InputError when a pitch point lies within |e| of the centre (the follower
// line cannot reach it).
FollowerSamples invert_follower(const PolarCurveFit& contour, const Eigen::Matrix2Xd& points,
                                const Follower& follower, Rotation rotation);

}  // namespace polarform
