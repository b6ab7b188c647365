// Conjugate (dual) plate cams for a double-roller follower: two cams on one shaft, the first
// driving the follower's roller as usual, the second driving a second roller carried rigidly by
// the same follower the other way, so that the follower is positively driven in both directions
// (Norton, Cam Design and Manufacturing Handbook, conjugate cams; Chen, Mechanics and Design of
// Cam Mechanisms, positive-drive cams).
//
// Translating roller follower: the second roller sits on the follower axis at the roller-centre
// distance D beyond the first, on the other side of the cam: its centre is the first's minus D·ŷ
// (fixed frame, plate_cam.h), so its distance from the cam centre follows −s. The second cam's
// base radius D − (y0 + stroke) − Rr must be > 0.
// Oscillating roller follower: a second arm on the same pivot, turned by arm-angle γ
// (counter-clockwise) from the first and of length L2; its roller centre is P + (L2/L)R(γ)(Q − P)
// for the first roller's centre Q. It must press the arm the other way at every cam angle.
// Both rollers have the radius Rr.
#pragma once

#include "designers/cam/plate_cam.h"
#include "designers/convert/polar_function.h"

namespace polarform {

struct ConjugateFollower {
  double roller_distance = 0.0;  // D, mm: translating roller followers
  double arm_angle = 0.0;        // γ, rad: oscillating roller followers
  double arm_length = 0.0;       // L2, mm: oscillating roller followers

  bool operator==(const ConjugateFollower&) const = default;
};

// The second roller as an image of the first. Throws InputError naming the conjugate field
// (roller-distance, arm-angle, arm-length) unless the follower has a roller, the rollers stay
// clear of each other and of the cam centre, and (oscillating) the second roller presses the arm
// against the first at every sampled cam angle.
RollerImage conjugate_roller(const PlateCam& cam, const ConjugateFollower& second);

// The second cam's contour as the converter's R(ψ); InputError naming the θ range and the remedy
// where it undercuts.
PolarFunction conjugate_contour_function(const PlateCam& cam, const ConjugateFollower& second);

}  // namespace polarform
