// An independent oracle for translating roller followers: the roller centre at a cam angle from
// the design's numbers and plain trigonometry (plate_cam.h states the convention: the follower
// axis parallel to +y through x = e, the centre at y = sqrt(Rp² − e²) + s(θ)), and a second roller
// a fixed distance D further down the same axis (conjugate cams), with no use of the designer's
// jets.
#pragma once

#include <Eigen/Geometry>
#include <cmath>

#include "designers/cam/cam_design.h"

namespace polarform::test {

struct TranslatingOracle {
  CamProgram program;
  double rb = 0, rr = 0, e = 0;
  int sigma = 1;  // sense of rotation (+1: counter-clockwise)

  // The oracle of a translating roller design.
  static TranslatingOracle of(const CamDesign& d) {
    return {make_program(d), d.base_radius, d.follower.roller_radius, d.follower.offset,
            sense(d.rotation)};
  }

  Eigen::Vector2d roller_centre(double theta) const {
    const double rp = rb + rr;
    return {e, std::sqrt(rp * rp - e * e) + program(theta)};
  }
  // Fixed frame to cam frame at θ: turned back by σθ.
  Eigen::Vector2d to_cam(const Eigen::Vector2d& x, double theta) const {
    return Eigen::Rotation2Dd(-sigma * theta) * x;
  }
  // The first roller's centre and the second's, D below it, in the cam frame.
  Eigen::Vector2d first(double theta) const { return to_cam(roller_centre(theta), theta); }
  Eigen::Vector2d second(double theta, double d) const {
    return to_cam(roller_centre(theta) - Eigen::Vector2d(0, d), theta);
  }
};

}  // namespace polarform::test
