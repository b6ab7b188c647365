// PlateCam: a plate (disk) cam driving a translating follower — knife-edge, roller or flat-faced,
// radial or offset — and its exact geometry: pitch curve, contour, pressure angle, radii of
// curvature. Norton, Cam Design and Manufacturing Handbook; Chen, Mechanics and Design of Cam
// Mechanisms.
//
// Convention. Cam centre at the origin; the follower axis is parallel to +y through x = e (the
// offset); the follower's reference point (knife tip, roller centre, the face's point on the axis)
// is at y = y0 + s(θ) with y0 = sqrt(Rp² - e²), Rp = Rb (knife-edge) or Rb + Rr (roller), and
// y0 = Rb for a flat face (perpendicular to the axis). The cam turns by θ (counter-clockwise or
// clockwise, sense σ = ±1); curves are given in the cam-fixed frame (the exported part), which
// coincides with the fixed frame at θ = 0 — so at θ = 0 the follower sits on the +y side at x = e.
// Rb is the base radius: the smallest circle about the cam centre tangent to the contour (s = 0).
#pragma once

#include <Eigen/Core>

#include "designers/cam/cam_frame.h"
#include "designers/cam/cam_program.h"
#include "designers/cam/jet.h"

namespace polarform {

enum class FollowerKind { KnifeEdge, Roller, FlatFaced };

struct Follower {
  FollowerKind kind = FollowerKind::Roller;
  double offset = 0.0;         // e, mm (no effect on a flat face's geometry)
  double roller_radius = 0.0;  // Rr, mm, roller only

  bool operator==(const Follower&) const = default;
};

// Everything the analyses read at one cam angle.
struct CamSample {
  double theta = 0.0;
  double s = 0.0, v = 0.0, a = 0.0, j = 0.0;  // mm, mm/rad, mm/rad², mm/rad³
  // Angle between the contact normal and the follower's direction of travel, radians; positive
  // during a rise of a radial follower: atan2(s' - σe, y0 + s); 0 for a flat face.
  double pressure_angle = 0.0;
  // Signed curvatures (1/mm), positive where the curve is convex (bulges away from the centre).
  double pitch_curvature = 0.0;
  double contour_curvature = 0.0;
  // Signed |dC/dθ| of the contour (mm/rad): > 0 where the contour is regular; <= 0 marks an
  // undercut (roller: |P'|(1 - Rr κ_pitch); flat face: Rb + s + s''; knife-edge: |P'|).
  double contour_speed = 0.0;
};

class PlateCam {
 public:
  // Throws InputError unless Rb > 0, Rr > 0 for a roller (ignored otherwise) and |e| < Rp for a
  // knife-edge or roller follower.
  PlateCam(CamProgram program, Follower follower, double base_radius, Rotation rotation = Rotation::CounterClockwise);

  const CamProgram& program() const { return program_; }
  const Follower& follower() const { return follower_; }
  double base_radius() const { return base_radius_; }
  Rotation rotation() const { return rotation_; }
  int sense() const { return polarform::sense(rotation_); }
  // Rb + Rr for a roller, Rb otherwise.
  double prime_radius() const;

  // Pitch curve (path of the follower's reference point) and contour (contact point) in the cam
  // frame: θ-derivatives 0..d (d <= 3) into out[0..d].
  void pitch(double theta, int d, Eigen::Vector2d* out) const;
  void contour(double theta, int d, Eigen::Vector2d* out) const;
  // As above for θ in [start, end] of `segment`, evaluating that segment only (one-sided values
  // at its ends).
  void contour_in_segment(int segment, double theta, int d, Eigen::Vector2d* out) const;

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

  CamProgram program_;
  Follower follower_;
  double base_radius_;
  Rotation rotation_;
};

}  // namespace polarform
