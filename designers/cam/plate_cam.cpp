#include "designers/cam/plate_cam.h"

#include <cmath>
#include <limits>
#include <string>

#include "src/error.h"
#include "src/number_text.h"

namespace polarform {
namespace {

// cos(σθ) and sin(σθ) as jets in θ.
struct RotationJets {
  Jet cos, sin;
  RotationJets(double theta, int sigma, int order) {
    const double c = std::cos(sigma * theta), s = std::sin(sigma * theta);
    const double cos_d[5] = {c, -sigma * s, -c, sigma * s, c};
    const double sin_d[5] = {s, sigma * c, -s, -sigma * c, s};
    cos = Jet::from(cos_d, order);
    sin = Jet::from(sin_d, order);
  }
};

// Rotation of a follower-frame point by -σθ into the cam frame, with θ-derivatives.
void rotate_into_cam_frame(const Jet& x, const Jet& y, const RotationJets& r, Jet* out) {
  out[0] = x * r.cos + y * r.sin;
  out[1] = y * r.cos - x * r.sin;
}

// Signed curvature of a cam-frame curve, positive where convex: the curve runs clockwise for σ = +1.
double signed_curvature(const Jet* xy, int sigma) {
  const double x1 = xy[0][1], y1 = xy[1][1], x2 = xy[0][2], y2 = xy[1][2];
  const double speed2 = x1 * x1 + y1 * y1;
  return -sigma * (x1 * y2 - y1 * x2) / (speed2 * std::sqrt(speed2));
}

double radius(double curvature) {
  return curvature == 0.0 ? std::numeric_limits<double>::infinity() : 1.0 / curvature;
}

}  // namespace

PlateCam::PlateCam(CamProgram program, Follower follower, double base_radius, Rotation rotation)
    : program_(std::move(program)), follower_(follower), base_radius_(base_radius), rotation_(rotation) {
  if (!std::isfinite(base_radius_) || !(base_radius_ > 0))
    throw InputError("plate cam: base radius must be a positive number of mm, got " + number_text(base_radius_));
  if (!std::isfinite(follower_.offset)) throw InputError("plate cam: follower offset is not finite");
  if (follower_.kind == FollowerKind::Roller &&
      (!std::isfinite(follower_.roller_radius) || !(follower_.roller_radius > 0)))
    throw InputError("plate cam: roller radius must be a positive number of mm, got " +
                     number_text(follower_.roller_radius));
  if (follower_.kind != FollowerKind::FlatFaced && !(std::abs(follower_.offset) < prime_radius()))
    throw InputError("plate cam: follower offset |e| = " + number_text(std::abs(follower_.offset)) +
                     " mm must be below the prime radius " + number_text(prime_radius()) + " mm");
}

double PlateCam::prime_radius() const {
  return follower_.kind == FollowerKind::Roller ? base_radius_ + follower_.roller_radius : base_radius_;
}

double PlateCam::rest_height() const {
  if (follower_.kind == FollowerKind::FlatFaced) return base_radius_;
  const double rp = prime_radius(), e = follower_.offset;
  return std::sqrt(rp * rp - e * e);
}

// Norton, Cam Design and Manufacturing Handbook (offset followers, cam profiles): pitch curve of
// an offset follower; roller contour as the inner envelope, the pitch point minus Rr along the pitch
// normal; flat face: the envelope of the face lines touches at x = σ s'.
void PlateCam::curves(const double* s, double theta, int order, Jet* pitch_xy, Jet* contour_xy) const {
  const int sigma = sense();
  const double e = follower_.offset;
  const Jet S = Jet::from(s, order + 1);
  const Jet qx(e, order), qy = S + rest_height();
  const RotationJets rotation(theta, sigma, order);
  rotate_into_cam_frame(qx, qy, rotation, pitch_xy);
  if (!contour_xy) return;
  switch (follower_.kind) {
    case FollowerKind::KnifeEdge:
      contour_xy[0] = pitch_xy[0];
      contour_xy[1] = pitch_xy[1];
      return;
    case FollowerKind::Roller: {
      // Outward pitch normal in the follower frame: (e - σ s', y0 + s) / |.|.
      const Jet mx = Jet(e, order) + (-sigma) * S.derivative(), my = qy;
      const Jet norm = sqrt(mx * mx + my * my);
      const double rr = follower_.roller_radius;
      rotate_into_cam_frame(qx + (-rr) * (mx / norm), qy + (-rr) * (my / norm), rotation, contour_xy);
      return;
    }
    case FollowerKind::FlatFaced:
      rotate_into_cam_frame(double(sigma) * S.derivative(), S + base_radius_, rotation, contour_xy);
      return;
  }
}

void PlateCam::pitch(double theta, int d, Eigen::Vector2d* out) const {
  if (d < 0 || d > 3) throw InputError("plate cam: derivative order " + std::to_string(d) + " outside [0, 3]");
  double s[5];
  program_.derivatives(theta, d + 1, s);
  Jet xy[2];
  curves(s, theta, d, xy, nullptr);
  for (int k = 0; k <= d; ++k) out[k] = {xy[0][k], xy[1][k]};
}

void PlateCam::contour(double theta, int d, Eigen::Vector2d* out) const {
  theta = wrap_angle(theta);
  contour_in_segment(program_.segment_index(theta), theta, d, out);
}

void PlateCam::contour_in_segment(int segment, double theta, int d, Eigen::Vector2d* out) const {
  if (d < 0 || d > 3) throw InputError("plate cam: derivative order " + std::to_string(d) + " outside [0, 3]");
  const MotionSegment& seg = program_.segments().at(segment);
  double s[5];
  seg.derivatives(theta, d + 1, s);
  Jet pitch_xy[2], contour_xy[2];
  curves(s, theta, d, pitch_xy, contour_xy);
  for (int k = 0; k <= d; ++k) out[k] = {contour_xy[0][k], contour_xy[1][k]};
}

double PlateCam::pressure_angle(double theta) const { return sample(theta).pressure_angle; }

double PlateCam::pitch_radius_of_curvature(double theta) const { return radius(sample(theta).pitch_curvature); }

double PlateCam::contour_radius_of_curvature(double theta) const {
  return radius(sample(theta).contour_curvature);
}

CamSample PlateCam::sample(double theta) const {
  theta = wrap_angle(theta);
  return sample_in_segment(program_.segment_index(theta), theta);
}

CamSample PlateCam::sample_in_segment(int segment, double theta) const {
  const MotionSegment& seg = program_.segments().at(segment);
  double s[4];
  seg.derivatives(theta, 3, s);
  Jet pitch_xy[2], contour_xy[2];
  curves(s, theta, 2, pitch_xy, contour_xy);
  const int sigma = sense();
  CamSample out;
  out.theta = theta;
  out.s = s[0], out.v = s[1], out.a = s[2], out.j = s[3];
  out.pitch_curvature = signed_curvature(pitch_xy, sigma);
  out.contour_curvature = signed_curvature(contour_xy, sigma);
  const double pitch_speed = std::hypot(pitch_xy[0][1], pitch_xy[1][1]);
  switch (follower_.kind) {
    case FollowerKind::KnifeEdge:
    case FollowerKind::Roller:  // Norton, Handbook (pressure angle): φ = atan((s' - e)/(s + sqrt(Rp² - e²)))
      out.pressure_angle = std::atan2(s[1] - sigma * follower_.offset, rest_height() + s[0]);
      out.contour_speed = follower_.kind == FollowerKind::KnifeEdge
                              ? pitch_speed
                              : pitch_speed * (1.0 - follower_.roller_radius * out.pitch_curvature);
      break;
    case FollowerKind::FlatFaced:  // Norton, Handbook (flat-faced follower): ρ = Rb + s + s''
      out.pressure_angle = 0.0;
      out.contour_speed = base_radius_ + s[0] + s[2];
      break;
  }
  return out;
}

}  // namespace polarform
