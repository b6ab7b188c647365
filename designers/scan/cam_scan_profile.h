// The planar profile of a scanned plate cam: a 2D scan (a CMM or optical profile: a planar cloud)
// is taken as it is; a 3D scan (both faces, the side, the bore) gets its axis from the two faces
// (a common plane normal fitted to them, refined from the cloud's direction of least scatter) and
// is sliced in the band of ±thickness/4 about mid-thickness, which holds only side and bore
// points (Kantz 2003, slicing). The centre of rotation is given, or found as the centre of the
// bore: the inner loop of points, split off at the widest gap in radius and fitted by a circle.
#pragma once

#include <Eigen/Core>
#include <numbers>
#include <optional>
#include <string>

#include "src/fit/circle_fit.h"
#include "src/fit/local_frame.h"

namespace polarform {

// The widest sector about the centre of rotation that the contour may leave empty: a plate cam's
// contour goes round its axis, and a centre outside it (a mistyped --center) leaves a wide one.
constexpr double kMaxContourGap = std::numbers::pi / 2;

// The largest rms distance of a 3D scan's face points from their planes, as a fraction of the
// scan's radius (largest distance from its centroid): a plate cam has two flat faces (scanner
// noise: ~0.1 %), a sphere or a blob has none (a sphere's caps: 6 %).
constexpr double kMaxFaceFlatness = 0.01;

struct CamProfileOptions {
  std::optional<Eigen::Vector3d> axis;    // the cam's axis; estimated when absent
  std::optional<Eigen::Vector3d> centre;  // a point on the axis; the bore's centre when absent
};

struct CamProfile {
  // The cam plane: origin = centre of rotation (on the mid-plane of a 3D scan), k = axis,
  // i = the input's x (made orthogonal to k; y when x is near the axis), j = k × i.
  LocalFrame plane;
  Eigen::Matrix2Xd contour;  // contour points in plane coordinates (centred on the rotation centre)
  Eigen::Matrix2Xd bore;     // bore points, same coordinates (empty when none)
  std::optional<CircleFit> bore_circle;
  bool three_d = false;
  double thickness = 0.0;       // 3D: distance between the faces' mean planes
  double face_flatness = 0.0;   // 3D: RMS distance of the face points from their planes
  std::size_t face_points = 0;  // 3D: points taken as face points
  std::string axis_reason, centre_reason;
};

// Throws InputError for fewer than 16 points, non-finite or coincident points, a 3D scan without
// two flat faces (kMaxFaceFlatness),
// no centre (none given and no bore found), or a contour that leaves a sector wider than
// kMaxContourGap about the centre, naming what was expected.
CamProfile extract_cam_profile(const Eigen::Matrix3Xd& points,
                               const CamProfileOptions& options = {});

// The points of `points` (2 x n) split at the widest gap in distance from `centre` into an inner
// loop (a bore: at least 12 points, the gap at least a tenth of the largest distance, a circle
// fit within 2 % of its radius) and the rest; `inner` is empty when there is no such loop.
void split_bore(const Eigen::Matrix2Xd& points, const Eigen::Vector2d& centre,
                Eigen::Matrix2Xd& inner, Eigen::Matrix2Xd& outer);

}  // namespace polarform
