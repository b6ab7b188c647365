#include "designers/cam/conjugate_cam.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>

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
RollerImage translating_second(const PlateCam& cam, double d, double r2) {
  const double rr = cam.follower().roller_radius;
  if (!std::isfinite(d) || !(d > rr + r2))
    throw InputError("conjugate roller-distance " + number_text(d) +
                     " mm: the rollers overlap; expected more than the sum of the roller radii, " +
                     number_text(rr + r2) + " mm");
  // The first roller's highest centre on the axis: y0 + stroke (plate_cam.h).
  const double y0 = std::sqrt(std::pow(cam.prime_radius(), 2) - std::pow(cam.follower().offset, 2));
  const double needed = y0 + cam.program().stroke() + r2;
  if (!(d > needed))
    throw InputError("conjugate roller-distance " + number_text(d) +
                     " mm is too small: the second roller would reach the cam centre; the second "
                     "cam's base radius D − (y0 + stroke) − Rr2 must be > 0, so D > " +
                     number_text(needed) + " mm");
  return {1.0, 0.0, Eigen::Vector2d(0.0, -d), r2};
}

// Oscillating follower: the second arm γ from the first about the pivot, L2 long.
RollerImage oscillating_second(const PlateCam& cam, const ConjugateFollower& c, double r2) {
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
  const RollerImage second{scale, c.arm_angle, p - turned_p, r2};
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
      if (!(q2[0].norm() > r2))
        throw InputError(
            "conjugate arm-length/arm-angle: the second roller reaches the cam centre "
            "at θ = " +
            degrees_text(theta) + " (its centre is " + number_text(q2[0].norm()) +
            " mm from it, the second roller's radius " + number_text(r2) + " mm)");
      if (!((q2[0] - q1[0]).norm() > rr + r2))
        throw InputError("conjugate arm-angle: the rollers overlap at θ = " + degrees_text(theta) +
                         " (centres " + number_text((q2[0] - q1[0]).norm()) +
                         " mm apart, less than the sum of the roller radii)");
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

double second_roller_radius(const PlateCam& cam, const ConjugateFollower& second) {
  return second.roller_radius > 0 ? second.roller_radius : cam.follower().roller_radius;
}

RollerImage conjugate_roller(const PlateCam& cam, const ConjugateFollower& second) {
  const FollowerKind kind = cam.follower().kind;
  if (!std::isfinite(second.roller_radius) || second.roller_radius < 0)
    throw InputError(
        "conjugate roller-radius must be a positive number of mm (or 0 for the "
        "first roller's), got " +
        number_text(second.roller_radius));
  const double r2 = second_roller_radius(cam, second);
  if (kind == FollowerKind::Roller) return translating_second(cam, second.roller_distance, r2);
  if (kind == FollowerKind::OscillatingRoller) return oscillating_second(cam, second, r2);
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

namespace {

// The roller centre's unit path direction in the cam frame (sign free): the follower axis
// (translating) or perpendicular to the line from the pivot (oscillating).
Eigen::Vector2d path_direction(const PlateCam& cam, double theta, const Eigen::Vector2d& centre) {
  const Eigen::Rotation2Dd to_cam(-cam.sense() * theta);
  if (!is_oscillating(cam.follower().kind)) return to_cam * Eigen::Vector2d(0.0, 1.0);
  const Eigen::Vector2d r = centre - to_cam * cam.pivot();
  return Eigen::Vector2d(-r.y(), r.x()).normalized();
}

// The signed distance along the unit normal n from the exact point c to the curve: the curve point
// on the line c + t n, by Newton steps on (C(u) − c)·n⊥ = 0 from the parameter of c's polar angle.
double normal_deviation(const NurbsCurve2d& curve, const BaseCircle& base, const Eigen::Vector2d& c,
                        const Eigen::Vector2d& n) {
  const Eigen::Vector2d t(-n.y(), n.x());
  double u = base.parameter(std::atan2(c.y(), c.x()));
  const double lo = curve.front(), hi = curve.back(), period = hi - lo;
  for (int it = 0; it < 12; ++it) {
    const auto d = curve.derivatives(u, 1);
    const double f = (d[0] - c).dot(t), df = d[1].dot(t);
    if (df == 0.0) break;
    const double step = f / df;
    u -= step;
    if (u < lo) u += period;  // a closed profile: wrap
    if (u > hi) u -= period;
    if (std::abs(step) < 1e-15 * std::max(1.0, period)) break;
  }
  return (curve.point(u) - c).dot(n);
}

}  // namespace

SecondContact conjugate_contact(const PlateCam& cam, const RollerImage& second, int segment,
                                double theta) {
  Eigen::Vector2d q[3], c[3];
  cam.roller_image_in_segment(segment, theta, 2, second, q, c);
  const Eigen::Vector2d n = (q[0] - c[0]).normalized();  // out of the cam, towards the roller
  SecondContact out;
  // κ = −c''·n / |c'|²: > 0 where the contour bulges out (its acceleration points into the cam).
  const double speed2 = c[1].squaredNorm(), kappa = speed2 > 0 ? -c[2].dot(n) / speed2 : 0.0;
  out.contour_radius = kappa != 0 ? 1 / kappa : std::numeric_limits<double>::infinity();
  if (is_oscillating(cam.follower().kind)) {
    const Eigen::Vector2d pc = Eigen::Rotation2Dd(-cam.sense() * theta) * cam.pivot();
    out.lever = std::abs(cross(q[0] - pc, n));
  }
  return out;
}

CentreDistanceError conjugate_centre_distance_error(
    const PlateCam& cam, const ConjugateFollower& second, const NurbsCurve2d& first_curve,
    const BaseCircle& first_base, const NurbsCurve2d& second_curve, const BaseCircle& second_base,
    int per_revolution) {
  const RollerImage first{1.0, 0.0, Eigen::Vector2d::Zero(), cam.follower().roller_radius};
  const RollerImage other = conjugate_roller(cam, second);
  CentreDistanceError out;
  const auto& segments = cam.program().segments();
  for (int k = 0; k < static_cast<int>(segments.size()); ++k) {
    const double a = segments[k].start(), b = segments[k].end();
    const int n =
        std::max(8, static_cast<int>(std::ceil(per_revolution * (b - a) / (2 * std::numbers::pi))));
    for (int i = 0; i <= n; ++i) {
      const double theta = i == n ? b : a + (b - a) * i / n;
      double play = 0.0;
      for (const auto& [image, curve, base, share] :
           {std::tuple{&first, &first_curve, &first_base, other.scale},
            std::tuple{&other, &second_curve, &second_base, 1.0}}) {
        Eigen::Vector2d q[1], c[1];
        cam.roller_image_in_segment(k, theta, 0, *image, q, c);
        const Eigen::Vector2d normal = (q[0] - c[0]).normalized();
        const double cos_phi = std::abs(normal.dot(path_direction(cam, theta, q[0])));
        play += share * normal_deviation(*curve, *base, c[0], normal) / cos_phi;
      }
      ++out.samples;
      if (std::abs(play) > out.max_error) out.max_error = std::abs(play), out.theta = theta;
    }
  }
  return out;
}

}  // namespace polarform
