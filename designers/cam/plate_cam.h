// PlateCam: a plate (disk) cam driving a translating follower — knife-edge, roller or flat-faced,
// radial or offset — or an oscillating (swing-arm) roller or flat-faced follower, and its exact
// geometry: pitch curve, contour, pressure angle, radii of curvature. Norton, Cam Design and
// Manufacturing Handbook; Chen, Mechanics and Design of Cam Mechanisms.
//
// Convention. Cam centre at the origin; the follower axis is parallel to +y through x = e (the
// offset); the follower's reference point (knife tip, roller centre, the face's point on the axis)
// is at y = y0 + s(θ) with y0 = sqrt(Rp² - e²), Rp = Rb (knife-edge) or Rb + Rr (roller), and
// y0 = Rb for a flat face (perpendicular to the axis). The cam turns by θ (counter-clockwise or
// clockwise, sense σ = ±1); curves are given in the cam-fixed frame (the exported part), which
// coincides with the fixed frame at θ = 0 — so at θ = 0 the follower sits on the +y side at x = e.
// Rb is the base radius: the smallest circle about the cam centre tangent to the contour (s = 0).
//
// Oscillating followers. The arm turns about a fixed pivot P at distance d (pivot-distance) from
// the cam centre, on the +x side (pivot_side = +1) or the -x side (-1). s(θ) is the arm's swing in
// degrees from its rest position, positive away from the cam. Roller: the roller centre sits at
// (0, Rp), Rp = Rb + Rr, at s = 0, at distance L (arm-length) from P. Flat face: the face line is
// at signed distance f (face-offset, > 0 when the pivot lies on the far side of the face from the
// cam) from P and touches the base circle at (0, Rb) at s = 0, so P = (±sqrt(d² − (Rb + f)²), Rb +
// f).
#pragma once

#include <Eigen/Core>

#include "designers/cam/cam_frame.h"
#include "designers/cam/cam_program.h"
#include "designers/cam/jet.h"

namespace polarform {

enum class FollowerKind { KnifeEdge, Roller, FlatFaced, OscillatingRoller, OscillatingFlatFaced };

inline bool is_oscillating(FollowerKind k) {
  return k == FollowerKind::OscillatingRoller || k == FollowerKind::OscillatingFlatFaced;
}
inline bool has_roller(FollowerKind k) {
  return k == FollowerKind::Roller || k == FollowerKind::OscillatingRoller;
}
inline bool is_flat_faced(FollowerKind k) {
  return k == FollowerKind::FlatFaced || k == FollowerKind::OscillatingFlatFaced;
}

// A roller carried rigidly by the follower, seen from its roller: its centre is
// scale·R(turn)·Q + shift in the fixed frame, Q the follower's own roller centre (a similarity
// that commutes with the cam's rotation), and its envelope on the turning cam lies `radius` from
// that centre towards the cam (radius < 0: away from it). The follower's roller is {1, 0, 0, Rr};
// a groove's outer flank {1, 0, 0, −Rr}; a conjugate cam's roller conjugate_cam.h.
struct RollerImage {
  double scale = 1.0, turn = 0.0;  // turn: rad, counter-clockwise
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();
  double radius = 0.0;
};

struct Follower {
  FollowerKind kind = FollowerKind::Roller;
  double offset = 0.0;         // e, mm, translating followers (no effect on a flat face's geometry)
  double roller_radius = 0.0;  // Rr, mm, rollers
  double pivot_distance = 0.0;  // d, mm, oscillating followers: cam centre to the arm pivot
  double arm_length = 0.0;      // L, mm, oscillating roller: pivot to roller centre
  double face_offset = 0.0;     // f, mm, oscillating flat face: face line to pivot (signed)
  int pivot_side = 1;           // +1: pivot on the +x side of the follower's rest line, -1: -x

  bool operator==(const Follower&) const = default;
};

// Everything the analyses read at one cam angle.
struct CamSample {
  double theta = 0.0;
  // mm, mm/rad, mm/rad², mm/rad³ (oscillating followers: the arm's swing in °, °/rad, ...)
  double s = 0.0, v = 0.0, a = 0.0, j = 0.0;
  // Angle between the contact normal and the direction of travel of the follower's contact point,
  // radians; positive during a rise of a radial follower: atan2(s' - σe, y0 + s); 0 for a
  // translating flat face. Oscillating followers: the travel is perpendicular to the line from
  // the pivot (pressure_angle.h).
  double pressure_angle = 0.0;
  // Signed curvatures (1/mm), positive where the curve is convex (bulges away from the centre).
  double pitch_curvature = 0.0;
  double contour_curvature = 0.0;
  // Signed |dC/dθ| of the contour (mm/rad): > 0 where the contour is regular; <= 0 marks an
  // undercut (roller: |P'|(1 - Rr κ_pitch); flat face: Rb + s + s''; knife-edge: |P'|).
  double contour_speed = 0.0;
  // Flat faces: where the face touches the cam, along the face (mm): from the follower axis along
  // +x of the fixed frame (translating, σ s' − e), from the foot of the pivot's perpendicular
  // (oscillating, along the face's direction J n); 0 for other followers.
  double face_contact = 0.0;
  // Oscillating followers: the moment arm (mm) about the pivot of the contact force the cam exerts
  // along the contact normal, signed positive when that force swings the arm away from the cam
  // (torque about the pivot = force · arm_lever); 0 for translating followers.
  double arm_lever = 0.0;
};

class PlateCam {
 public:
  // Throws InputError unless Rb > 0, Rr > 0 for a roller (ignored otherwise), |e| < Rp for a
  // translating knife-edge or roller follower, and an oscillating follower's pivot and arm reach
  // the base circle (see above); the arm's reach over the swing is checked by check_arm_swing.
  PlateCam(CamProgram program, Follower follower, double base_radius, Rotation rotation = Rotation::CounterClockwise);

  const CamProgram& program() const { return program_; }
  const Follower& follower() const { return follower_; }
  double base_radius() const { return base_radius_; }
  Rotation rotation() const { return rotation_; }
  int sense() const { return polarform::sense(rotation_); }
  // Rb + Rr for a roller, Rb otherwise.
  double prime_radius() const;
  // Oscillating followers: the pivot in the fixed frame, and the largest swing (°) before the
  // follower's reach from the cam centre stops growing (the arm lines up with the pivot).
  Eigen::Vector2d pivot() const;
  double max_arm_swing() const;
  // Oscillating followers: throws InputError naming `lift` when the program's swing leaves
  // [0, max_arm_swing()).
  void check_arm_swing() const;

  // Pitch curve (path of the follower's reference point) and contour (contact point) in the cam
  // frame: θ-derivatives 0..d (d <= 3) into out[0..d].
  void pitch(double theta, int d, Eigen::Vector2d* out) const;
  void contour(double theta, int d, Eigen::Vector2d* out) const;
  // As above for θ in [start, end] of `segment`, evaluating that segment only (one-sided values
  // at its ends).
  void contour_in_segment(int segment, double theta, int d, Eigen::Vector2d* out) const;

  // Rollers only (InputError otherwise): the centre path and the envelope of `image` in the cam
  // frame, θ-derivatives 0..d (d <= 3), θ in [start, end] of `segment` (one-sided at its ends).
  void roller_image_in_segment(int segment, double theta, int d, const RollerImage& image,
                               Eigen::Vector2d* centre, Eigen::Vector2d* contact) const;
  // The pitch curve as above, evaluating `segment` only.
  void pitch_in_segment(int segment, double theta, int d, Eigen::Vector2d* out) const;

  double pressure_angle(double theta) const;
  // Signed radii of curvature (mm), positive where convex; ±infinity at an inflection.
  double pitch_radius_of_curvature(double theta) const;
  double contour_radius_of_curvature(double theta) const;

  CamSample sample(double theta) const;
  // θ in [start, end] of `segment` (one-sided at its ends).
  CamSample sample_in_segment(int segment, double theta) const;

 private:
  // Pitch and contour points in the cam frame as jets of order `order` (<= 3) from s..s^(order+1).
  void curves(const double* s, double theta, int order, Jet* pitch_xy, Jet* contour_xy) const;
  double rest_height() const;  // y0
  // Rollers: the roller centre in the fixed frame as jets of S's order.
  void roller_centre(const Jet& S, Jet* xy) const;
  void place_pivot();          // pivot_ and swing_sign_ of an oscillating follower
  // Oscillating followers: the follower's reference point (roller centre, or the face's foot point
  // of the perpendicular from the origin) and the contact point in the fixed frame, as jets.
  // Flat face: its height h over the cam centre, h' / φ' (the contact along J n) and φ' (the line's
  // angular rate relative to the cam) into `face` when given.
  struct FaceLine {
    Jet h, lambda, phi_rate;
  };
  void oscillating_curves(const Jet& s, Jet* reference_xy, Jet* contact_xy,
                          FaceLine* face = nullptr) const;
  // Oscillating followers at one sample: pressure angle, contour speed and face contact.
  void oscillating_sample(const double* s, CamSample& out) const;

  CamProgram program_;
  Follower follower_;
  double base_radius_;
  Rotation rotation_;
  Eigen::Vector2d pivot_ = Eigen::Vector2d::Zero();  // fixed frame; oscillating followers only
  int swing_sign_ = 0;  // κ: the arm turns by κ·s counter-clockwise; oscillating followers only
};

}  // namespace polarform
