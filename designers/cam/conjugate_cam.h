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
// The second roller's radius Rr2 defaults to the first's, Rr.
#pragma once

#include "designers/cam/plate_cam.h"
#include "designers/convert/polar_function.h"
#include "src/base/base_circle.h"

namespace polarform {

struct ConjugateFollower {
  double roller_distance = 0.0;  // D, mm: translating roller followers
  double arm_angle = 0.0;        // γ, rad: oscillating roller followers
  double arm_length = 0.0;       // L2, mm: oscillating roller followers
  double roller_radius = 0.0;    // Rr2, mm: the second roller's; 0: the first's, Rr

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

// Rr2: the conjugate's roller-radius, or the first roller's when it gives none.
double second_roller_radius(const PlateCam& cam, const ConjugateFollower& second);

// The second roller's contact at cam angle θ of `segment` (one-sided at its ends): the second
// contour's signed radius of curvature there (mm, > 0 convex, ±inf flat) and, for an arm, the
// contact normal's moment arm about the pivot (mm, > 0; 0 for a translating follower).
struct SecondContact {
  double contour_radius = 0.0;
  double lever = 0.0;
};
SecondContact conjugate_contact(const PlateCam& cam, const RollerImage& second, int segment,
                                double theta);

// The double roller's centre-distance error of a converted pair, measured: at `per_revolution`
// cam angles (both ends of every segment included) the signed deviation δᵢ of each NURBS contour
// from the exact contact point along its normal (the curve point on the normal line, found by
// Newton steps from the base circle's parameter of the contact's polar angle), carried to the
// follower by the first-order rule Δ = δ / cos φ (φ the angle between the contour normal and the
// roller centre's path): the interference (> 0) or play (< 0) of the second roller along its path,
// (L2/L)·δ₁/cos φ₁ + δ₂/cos φ₂ (L2/L = 1 for a translating follower, whose rollers' centre
// distance it is). Second-order terms are O(δ²/ρ).
struct CentreDistanceError {
  double max_error = 0.0;  // mm, the largest |play|
  double theta = 0.0;      // rad, where
  int samples = 0;
};
CentreDistanceError conjugate_centre_distance_error(
    const PlateCam& cam, const ConjugateFollower& second, const NurbsCurve2d& first_curve,
    const BaseCircle& first_base, const NurbsCurve2d& second_curve, const BaseCircle& second_base,
    int per_revolution = 7200);

}  // namespace polarform
