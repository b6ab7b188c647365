#include "designers/cam/plate_cam.h"

#include <cmath>
#include <limits>
#include <string>

#include "src/error.h"
#include "src/number_text.h"
#include "src/units.h"

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

// J v: v turned by +90°.
Eigen::Vector2d perp(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Signed angle turning a into b, radians in (-π, π].
double angle_between(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::atan2(cross(a, b), a.dot(b));
}

// Angle between the contact normal and the travel direction w of the follower's contact point,
// from the contact's tangent t relative to the cam (fixed frame): atan2(t·w, −σ t·Jw), which is
// atan2(s' − σe, y0 + s) for a translating follower (Norton, Handbook, pressure angle).
double pressure_angle_from(const Eigen::Vector2d& t, const Eigen::Vector2d& w, int sigma) {
  return std::atan2(t.dot(w), -sigma * t.dot(perp(w)));
}

// The envelope of a circle of radius r about the roller centre q (fixed frame, jets) on the
// turning cam, on the cam's side: q − r m/|m| with m = q + σ J q', the outward normal of the
// centre's path relative to the cam (its relative velocity q' − σ J q turned by σ·90°). Chen,
// Mechanics and Design of Cam Mechanisms, the envelope of a roller follower.
void roller_envelope(const Jet* q, int sigma, double r, Jet* out) {
  const Jet mx = q[0] + (-sigma) * q[1].derivative(), my = q[1] + double(sigma) * q[0].derivative();
  const Jet norm = sqrt(mx * mx + my * my);
  out[0] = q[0] + (-r) * (mx / norm);
  out[1] = q[1] + (-r) * (my / norm);
}

// The arm angle a = κ s π/180 (radians) as a jet from s in degrees.
Jet arm_angle(const Jet& s, int swing_sign) { return (swing_sign * kRadiansPerDegree) * s; }

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
  if (follower_.kind == FollowerKind::OscillatingRoller &&
      (!std::isfinite(follower_.roller_radius) || !(follower_.roller_radius > 0)))
    throw InputError("plate cam: roller radius must be a positive number of mm, got " +
                     number_text(follower_.roller_radius));
  if (is_oscillating(follower_.kind)) {
    place_pivot();
    check_arm_swing();
    return;
  }
  if (follower_.kind != FollowerKind::FlatFaced && !(std::abs(follower_.offset) < prime_radius()))
    throw InputError("plate cam: follower offset |e| = " + number_text(std::abs(follower_.offset)) +
                     " mm must be below the prime radius " + number_text(prime_radius()) + " mm");
}

// The pivot from d and L (roller: the triangle cam centre – pivot – roller centre at rest) or d
// and f (flat face), on the chosen side; κ makes a positive swing move the follower away.
void PlateCam::place_pivot() {
  const double d = follower_.pivot_distance;
  if (!std::isfinite(d) || !(d > 0))
    throw InputError("plate cam: pivot-distance must be a positive number of mm, got " +
                     number_text(d));
  if (follower_.pivot_side != 1 && follower_.pivot_side != -1)
    throw InputError("plate cam: pivot side must be +1 or -1");
  double y = 0.0;
  if (follower_.kind == FollowerKind::OscillatingRoller) {
    const double l = follower_.arm_length, rp = prime_radius();
    if (!std::isfinite(l) || !(l > 0))
      throw InputError("plate cam: arm-length must be a positive number of mm, got " +
                       number_text(l));
    if (!(std::abs(d - l) < rp && rp < d + l))
      throw InputError(
          "plate cam: the arm cannot put the roller on the prime circle: the roller centre "
          "at rest must be base-radius + roller-radius = " +
          number_text(rp) + " mm from the cam centre, but pivot-distance " + number_text(d) +
          " mm and arm-length " + number_text(l) + " mm reach only between " +
          number_text(std::abs(d - l)) + " and " + number_text(d + l) + " mm");
    y = (d * d - l * l + rp * rp) / (2 * rp);
  } else {
    const double f = follower_.face_offset;
    if (!std::isfinite(f)) throw InputError("plate cam: face-offset is not finite");
    y = base_radius_ + f;
    if (!(std::abs(y) < d))
      throw InputError(
          "plate cam: the face cannot touch the base circle: pivot-distance " + number_text(d) +
          " mm must exceed |base-radius + face-offset| = " + number_text(std::abs(y)) + " mm");
  }
  pivot_ = {follower_.pivot_side * std::sqrt(d * d - y * y), y};
  swing_sign_ = -follower_.pivot_side;
}

Eigen::Vector2d PlateCam::pivot() const { return pivot_; }

// The reach (roller centre's distance, face line's distance from the cam centre) grows with the
// swing until the arm (roller: pivot → roller centre; face: its normal) points along the pivot.
double PlateCam::max_arm_swing() const {
  if (!is_oscillating(follower_.kind)) return 0.0;
  const Eigen::Vector2d rest = follower_.kind == FollowerKind::OscillatingRoller
                                   ? Eigen::Vector2d(Eigen::Vector2d(0, prime_radius()) - pivot_)
                                   : Eigen::Vector2d(0, 1);
  return swing_sign_ * angle_between(rest, pivot_) * kDegreesPerRadian;
}

void PlateCam::check_arm_swing() const {
  if (!is_oscillating(follower_.kind)) return;
  double lowest = 0.0, highest = program_.stroke();
  constexpr int kSamples = 2880;
  for (int i = 0; i < kSamples; ++i) {
    const double s = program_(2 * std::numbers::pi * i / kSamples);
    lowest = std::min(lowest, s), highest = std::max(highest, s);
  }
  if (lowest < -1e-9)
    throw InputError(
        "plate cam: an oscillating follower's swing must stay >= 0° (the roller or face would "
        "cut into the base circle), the motion reaches " +
        number_text(lowest) + "°");
  const double limit = max_arm_swing();
  if (!(highest < limit))
    throw InputError("plate cam: the arm cannot swing the lift: with pivot-distance " +
                     number_text(follower_.pivot_distance) +
                     " mm it moves the follower away from the cam for at "
                     "most " +
                     number_text(limit) +
                     "° before lining up with the pivot, but the motion swings it " +
                     number_text(highest) + "° (reduce the lift or move the pivot)");
}

double PlateCam::prime_radius() const {
  return has_roller(follower_.kind) ? base_radius_ + follower_.roller_radius : base_radius_;
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
  const RotationJets rotation(theta, sigma, order);
  if (is_oscillating(follower_.kind)) {
    Jet reference[2], contact[2];
    oscillating_curves(S, reference, contour_xy ? contact : nullptr);
    rotate_into_cam_frame(reference[0], reference[1], rotation, pitch_xy);
    if (contour_xy) rotate_into_cam_frame(contact[0], contact[1], rotation, contour_xy);
    return;
  }
  const Jet qx(e, order + 1), qy = S + rest_height();  // both of S's order
  rotate_into_cam_frame(qx, qy, rotation, pitch_xy);
  if (!contour_xy) return;
  switch (follower_.kind) {
    case FollowerKind::KnifeEdge:
      contour_xy[0] = pitch_xy[0];
      contour_xy[1] = pitch_xy[1];
      return;
    case FollowerKind::Roller: {
      // The outward pitch normal in the follower frame is (e - σ s', y0 + s).
      const Jet q[2] = {qx, qy};
      Jet contact[2];
      roller_envelope(q, sigma, follower_.roller_radius, contact);
      rotate_into_cam_frame(contact[0], contact[1], rotation, contour_xy);
      return;
    }
    case FollowerKind::FlatFaced:
      rotate_into_cam_frame(double(sigma) * S.derivative(), S + base_radius_, rotation, contour_xy);
      return;
    case FollowerKind::OscillatingRoller:
    case FollowerKind::OscillatingFlatFaced:
      return;  // handled above
  }
}

// Fixed-frame follower geometry of an oscillating follower, the arm turned by a = κ s π/180 about
// the pivot P. Roller (Norton, Handbook, oscillating roller followers): centre Q = P + R(a)(Q0 −
// P); contact Q − Rr m/|m| with the outward pitch normal m = Q + σ J Q' (the relative velocity Q' −
// σ J Q turned by σ·90°). Flat face: the line X·n = h, n = R(a)(0, 1), h = P·n − f; its envelope in
// the turning cam touches at h n + (h'/φ') J n, φ' = a' − σ the line's angular rate relative to the
// cam.
void PlateCam::oscillating_curves(const Jet& S, Jet* reference_xy, Jet* contact_xy,
                                  FaceLine* face) const {
  const int sigma = sense();
  const Jet a = arm_angle(S, swing_sign_), c = cos(a), s = sin(a);
  const double px = pivot_.x(), py = pivot_.y();
  if (follower_.kind == FollowerKind::OscillatingRoller) {
    const double wx = -px, wy = prime_radius() - py;  // Q0 − P
    const Jet qx = wx * c + (-wy) * s + px, qy = wx * s + wy * c + py;
    reference_xy[0] = qx, reference_xy[1] = qy;
    if (contact_xy) roller_envelope(reference_xy, sigma, follower_.roller_radius, contact_xy);
    return;
  }
  const Jet h = (-px) * s + py * c + (-follower_.face_offset);  // n = (−sin a, cos a)
  reference_xy[0] = (-1.0) * (h * s), reference_xy[1] = h * c;
  if (!contact_xy) return;
  const Jet phi_rate = a.derivative() + double(-sigma),
            lambda = h.derivative() / phi_rate;              // h'/φ'
  contact_xy[0] = (-1.0) * (h * s) + (-1.0) * (lambda * c);  // J n = (−cos a, −sin a)
  contact_xy[1] = h * c + (-1.0) * (lambda * s);
  if (face) *face = {h, lambda, phi_rate};
}

// Pressure angle (pressure_angle_from), signed contour speed and the face contact at one sample.
// The contact point's travel w is κ J (X − P): perpendicular to the line from the pivot.
void PlateCam::oscillating_sample(const double* s, CamSample& out) const {
  const int sigma = sense();
  const Jet S = Jet::from(s, 3);
  const double a = arm_angle(S, swing_sign_)[0];
  Jet reference[2], contact[2];
  FaceLine face;
  oscillating_curves(S, reference, contact, &face);
  if (follower_.kind == FollowerKind::OscillatingRoller) {
    const Eigen::Vector2d q(reference[0][0], reference[1][0]), dq(reference[0][1], reference[1][1]);
    const Eigen::Vector2d t = dq - sigma * perp(q), w = swing_sign_ * perp(q - pivot_);
    out.pressure_angle = pressure_angle_from(t, w.normalized(), sigma);
    const Eigen::Vector2d x(contact[0][0],
                            contact[1][0]);  // the push runs from x to the roller centre
    out.arm_lever = swing_sign_ * cross(x - pivot_, (q - x).normalized());
    return;  // contour speed: the roller's generic |P'|(1 − Rr κ_pitch)
  }
  const Eigen::Vector2d n(-std::sin(a), std::cos(a)), x(contact[0][0], contact[1][0]);
  const Eigen::Vector2d w = swing_sign_ * perp(x - pivot_);
  out.pressure_angle = pressure_angle_from(-sigma * perp(n), w.normalized(), sigma);
  out.arm_lever = swing_sign_ * cross(x - pivot_, n);  // the face is pushed along its normal n
  // Support function of the contour against the line angle φ: ρ = h + d²h/dφ², |dX/dθ| = ρ |φ'|.
  const double phi_rate = face.phi_rate[0];
  out.contour_speed = (face.h[0] + face.lambda[1] / phi_rate) * (-sigma * phi_rate);
  // Along J n from the foot of the pivot's perpendicular, positive towards the cam's side.
  out.face_contact = follower_.pivot_side * (face.lambda[0] - pivot_.dot(perp(n)));
}

void PlateCam::pitch(double theta, int d, Eigen::Vector2d* out) const {
  if (d < 0 || d > 3) throw InputError("plate cam: derivative order " + std::to_string(d) + " outside [0, 3]");
  double s[5];
  program_.derivatives(theta, d + 1, s);
  Jet xy[2];
  curves(s, theta, d, xy, nullptr);
  for (int k = 0; k <= d; ++k) out[k] = {xy[0][k], xy[1][k]};
}

void PlateCam::pitch_in_segment(int segment, double theta, int d, Eigen::Vector2d* out) const {
  if (d < 0 || d > 3)
    throw InputError("plate cam: derivative order " + std::to_string(d) + " outside [0, 3]");
  double s[5];
  program_.segments().at(segment).derivatives(theta, d + 1, s);
  Jet xy[2];
  curves(s, theta, d, xy, nullptr);
  for (int k = 0; k <= d; ++k) out[k] = {xy[0][k], xy[1][k]};
}

void PlateCam::roller_centre(const Jet& S, Jet* xy) const {
  if (is_oscillating(follower_.kind)) {
    oscillating_curves(S, xy, nullptr);
    return;
  }
  xy[0] = Jet(follower_.offset, S.order());
  xy[1] = S + rest_height();
}

// The image's centre is a similarity of the roller centre; the similarity commutes with the cam's
// rotation, so the envelope construction of the follower's own roller applies unchanged.
void PlateCam::roller_image_in_segment(int segment, double theta, int d, const RollerImage& image,
                                       Eigen::Vector2d* centre, Eigen::Vector2d* contact) const {
  if (!has_roller(follower_.kind))
    throw InputError("plate cam: a roller image needs a roller follower");
  if (d < 0 || d > 3)
    throw InputError("plate cam: derivative order " + std::to_string(d) + " outside [0, 3]");
  double s[5];
  program_.segments().at(segment).derivatives(theta, d + 1, s);
  Jet q[2];
  roller_centre(Jet::from(s, d + 1), q);
  const double a = image.scale * std::cos(image.turn), b = image.scale * std::sin(image.turn);
  const Jet image_q[2] = {a * q[0] + (-b) * q[1] + image.shift.x(),
                          b * q[0] + a * q[1] + image.shift.y()};
  Jet envelope[2], centre_xy[2], contact_xy[2];
  roller_envelope(image_q, sense(), image.radius, envelope);
  const RotationJets rotation(theta, sense(), d);
  rotate_into_cam_frame(image_q[0], image_q[1], rotation, centre_xy);
  rotate_into_cam_frame(envelope[0], envelope[1], rotation, contact_xy);
  for (int k = 0; k <= d; ++k) {
    centre[k] = {centre_xy[0][k], centre_xy[1][k]};
    contact[k] = {contact_xy[0][k], contact_xy[1][k]};
  }
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
    case FollowerKind::OscillatingRoller:
      out.contour_speed = pitch_speed * (1.0 - follower_.roller_radius * out.pitch_curvature);
      oscillating_sample(s, out);
      break;
    case FollowerKind::OscillatingFlatFaced:
      oscillating_sample(s, out);
      break;
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
      out.face_contact = sigma * s[1] - follower_.offset;
      break;
  }
  return out;
}

}  // namespace polarform
