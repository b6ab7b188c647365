#include "designers/cam/conjugate_cam.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "designers/cam/contour_polar_function.h"
#include "src/error.h"
#include "src/number_text.h"

namespace polarform {
namespace {

constexpr int kSamples = 2880;  // cam angles checked over a revolution

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Translating follower: the second roller D below the first on the follower axis.
RollerImage translating_second(const PlateCam& cam, double d) {
  const double rr = cam.follower().roller_radius;
  if (!std::isfinite(d) || !(d > 2 * rr))
    throw InputError("conjugate roller-distance " + number_text(d) +
                     " mm: the rollers overlap; expected more than twice the roller radius, " +
                     number_text(2 * rr) + " mm");
  // The first roller's highest centre on the axis: y0 + stroke (plate_cam.h).
  const double y0 = std::sqrt(std::pow(cam.prime_radius(), 2) - std::pow(cam.follower().offset, 2));
  const double needed = y0 + cam.program().stroke() + rr;
  if (!(d > needed))
    throw InputError("conjugate roller-distance " + number_text(d) +
                     " mm is too small: the second roller would reach the cam centre; the second "
                     "cam's base radius D − (y0 + stroke) − Rr must be > 0, so D > " +
                     number_text(needed) + " mm");
  return {1.0, 0.0, Eigen::Vector2d(0.0, -d), rr};
}

// Oscillating follower: the second arm γ from the first about the pivot, L2 long.
RollerImage oscillating_second(const PlateCam& cam, const ConjugateFollower& c) {
  const double rr = cam.follower().roller_radius, l = cam.follower().arm_length;
  if (!std::isfinite(c.arm_length) || !(c.arm_length > 0))
    throw InputError("conjugate arm-length must be a positive number of mm, got " +
                     number_text(c.arm_length));
  if (!std::isfinite(c.arm_angle) || !(std::abs(c.arm_angle) < std::numbers::pi))
    throw InputError("conjugate arm-angle must lie in (−180°, 180°), got " +
                     degrees_text(c.arm_angle));
  const Eigen::Vector2d p = cam.pivot();
  const double scale = c.arm_length / l;
  const Eigen::Vector2d turned_p(
      scale * (std::cos(c.arm_angle) * p.x() - std::sin(c.arm_angle) * p.y()),
      scale * (std::sin(c.arm_angle) * p.x() + std::cos(c.arm_angle) * p.y()));
  const RollerImage second{scale, c.arm_angle, p - turned_p, rr};
  const RollerImage first{1.0, 0.0, Eigen::Vector2d::Zero(), rr};
  const auto& segments = cam.program().segments();
  for (int k = 0; k < static_cast<int>(segments.size()); ++k) {
    const double a = segments[k].start(), b = segments[k].end();
    const int n =
        std::max(8, static_cast<int>(std::ceil(kSamples * (b - a) / (2 * std::numbers::pi))));
    for (int i = 0; i <= n; ++i) {
      const double theta = a + (b - a) * i / n;
      Eigen::Vector2d q1[1], c1[1], q2[1], c2[1];
      cam.roller_image_in_segment(k, theta, 0, first, q1, c1);
      cam.roller_image_in_segment(k, theta, 0, second, q2, c2);
      if (!(q2[0].norm() > rr))
        throw InputError(
            "conjugate arm-length/arm-angle: the second roller reaches the cam centre "
            "at θ = " +
            degrees_text(theta) + " (its centre is " + number_text(q2[0].norm()) +
            " mm from it, the roller radius " + number_text(rr) + " mm)");
      if (!((q2[0] - q1[0]).norm() > 2 * rr))
        throw InputError("conjugate arm-angle: the rollers overlap at θ = " + degrees_text(theta) +
                         " (centres " + number_text((q2[0] - q1[0]).norm()) +
                         " mm apart, less than twice the roller radius)");
      // The pivot in the cam frame, and each contact force's moment about it.
      const Eigen::Vector2d pc = Eigen::Rotation2Dd(-cam.sense() * theta) * p;
      const double m1 = cross(q1[0] - pc, q1[0] - c1[0]), m2 = cross(q2[0] - pc, q2[0] - c2[0]);
      if (!(m1 * m2 < 0))
        throw InputError(
            "conjugate arm-angle " + degrees_text(c.arm_angle) +
            ": the second cam does not press the arm back at θ = " + degrees_text(theta) +
            "; put the second arm's roller on the other side of the line from the "
            "cam centre to the pivot");
    }
  }
  return second;
}

}  // namespace

RollerImage conjugate_roller(const PlateCam& cam, const ConjugateFollower& second) {
  const FollowerKind kind = cam.follower().kind;
  if (kind == FollowerKind::Roller) return translating_second(cam, second.roller_distance);
  if (kind == FollowerKind::OscillatingRoller) return oscillating_second(cam, second);
  throw InputError("conjugate: conjugate cams need a roller or oscillating-roller follower, not " +
                   std::string(kind == FollowerKind::KnifeEdge ? "a knife edge" : "a flat face"));
}

PolarFunction conjugate_contour_function(const PlateCam& cam, const ConjugateFollower& second) {
  return roller_image_polar_function(
      cam, conjugate_roller(cam, second), "conjugate (second) contour",
      is_oscillating(cam.follower().kind)
          ? "lengthen the conjugate arm-length, reduce the roller radius or lengthen the segment"
          : "increase the conjugate roller-distance (the second cam grows), reduce the roller "
            "radius or lengthen the segment");
}

}  // namespace polarform
