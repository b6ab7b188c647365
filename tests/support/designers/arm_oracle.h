// An independent oracle for oscillating (swing-arm) followers: the arm's pivot, roller centre and
// face line at a cam angle from the design's numbers and plain trigonometry (plate_cam.h states the
// convention), with no use of the designer's jets. Tests measure contours and read-back curves
// against it: the roller contour is at the roller radius from the roller centres, the flat-faced
// cam's support function is the face's height.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "designers/cam/cam_design.h"

namespace polarform::test {

struct ArmOracle {
  CamProgram program;  // the arm's swing in degrees
  double rb = 0, rr = 0, d = 0, l = 0, f = 0;
  int side = 1, sigma = 1;  // pivot side (+1: +x), sense of rotation (+1: counter-clockwise)
  bool roller = true;

  // The oracle of an oscillating design.
  static ArmOracle of(const CamDesign& d) {
    return {make_program(d),
            d.base_radius,
            d.follower.roller_radius,
            d.follower.pivot_distance,
            d.follower.arm_length,
            d.follower.face_offset,
            d.follower.pivot_side,
            sense(d.rotation),
            d.follower.kind == FollowerKind::OscillatingRoller};
  }

  static Eigen::Vector2d rotate(const Eigen::Vector2d& v, double angle) {
    return Eigen::Rotation2Dd(angle) * v;
  }

  Eigen::Vector2d pivot() const {
    const double rp = rb + rr;
    // Roller: the pivot is d from the centre and L from (0, Rp); face: the face y = Rb at rest is
    // f from the pivot.
    const double y = roller ? (d * d - l * l + rp * rp) / (2 * rp) : rb + f;
    return {side * std::sqrt(d * d - y * y), y};
  }
  // The arm's turn (counter-clockwise positive) at θ: a positive swing moves the follower away.
  double arm_turn(double theta) const { return -side * program(theta) * std::numbers::pi / 180; }
  Eigen::Vector2d roller_centre(double theta) const {
    const Eigen::Vector2d p = pivot();
    return p + rotate(Eigen::Vector2d(0, rb + rr) - p, arm_turn(theta));
  }
  // A second arm on the same pivot (conjugate cams), turned by gamma (rad, counter-clockwise) from
  // the first and l2 long: its roller centre.
  Eigen::Vector2d second_roller_centre(double theta, double gamma, double l2) const {
    const Eigen::Vector2d p = pivot();
    return p + rotate(roller_centre(theta) - p, gamma) * (l2 / l);
  }
  // Fixed frame to cam frame at θ: turned back by σθ.
  Eigen::Vector2d to_cam(const Eigen::Vector2d& x, double theta) const {
    return rotate(x, -sigma * theta);
  }
  // The face line X·n = h at θ in the fixed frame.
  Eigen::Vector2d face_normal(double theta) const {
    return rotate(Eigen::Vector2d(0, 1), arm_turn(theta));
  }
  double face_height(double theta) const { return pivot().dot(face_normal(theta)) - f; }
};

}  // namespace polarform::test
