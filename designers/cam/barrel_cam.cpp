#include "designers/cam/barrel_cam.h"

#include <cmath>
#include <numbers>
#include <string>

#include "designers/cam/displacement_polar_function.h"
#include "src/error.h"
#include "src/number_text.h"

namespace polarform {

BarrelCam::BarrelCam(CamProgram program, double pitch_radius, double z0, double roller_radius, Rotation rotation)
    : program_(std::move(program)), pitch_radius_(pitch_radius), z0_(z0), roller_radius_(roller_radius),
      rotation_(rotation) {
  if (!std::isfinite(pitch_radius_) || !(pitch_radius_ > 0))
    throw InputError("barrel cam: pitch radius must be a positive number of mm, got " + number_text(pitch_radius_));
  if (!std::isfinite(roller_radius_) || !(roller_radius_ > 0) || !(roller_radius_ < pitch_radius_))
    throw InputError("barrel cam: roller radius must be positive and below the pitch radius, got " +
                     number_text(roller_radius_) + " mm");
  if (!std::isfinite(z0_)) throw InputError("barrel cam: z0 is not finite");
}

PolarFunction BarrelCam::track_height() const { return displacement_polar_function(program_, rotation_, z0_); }

void BarrelCam::track_point(double theta, int d, Eigen::Vector3d* out) const {
  if (d < 0 || d > 3) throw InputError("barrel cam: derivative order " + std::to_string(d) + " outside [0, 3]");
  double s[4];
  program_.derivatives(theta, d, s);
  const double phi = follower_polar_angle(theta, rotation_), chain = -sense(rotation_);
  double factor = 1.0;  // (dφ/dθ)^k
  for (int k = 0; k <= d; ++k, factor *= chain) {
    const double a = phi + k * std::numbers::pi / 2;  // k-th derivative of (cos φ, sin φ)
    out[k] = {pitch_radius_ * factor * std::cos(a), pitch_radius_ * factor * std::sin(a), s[k]};
  }
  out[0].z() += z0_;
}

Eigen::Vector3d BarrelCam::roller_axis(double theta) const {
  const double phi = follower_polar_angle(theta, rotation_);
  return {std::cos(phi), std::sin(phi), 0.0};
}

double BarrelCam::pressure_angle(double theta, double t) const {
  if (!(t > 0)) throw InputError("barrel cam: distance along the roller axis must be positive");
  double s[2];
  program_.derivatives(theta, 1, s);
  return std::atan(s[1] / t);
}

// Envelope condition of the roller surface swept by θ: φ' t cos α + z' sin α = 0 with φ' = -σ,
// z' = s' (Chen, Mechanics and Design of Cam Mechanisms, cylindrical cams; solved in closed form).
Eigen::Vector3d BarrelCam::groove_wall_point(double theta, double t, int side) const {
  if (side != 1 && side != -1) throw InputError("barrel cam: groove wall side must be +1 or -1");
  if (!(t > 0)) throw InputError("barrel cam: distance along the roller axis must be positive");
  double s[2];
  program_.derivatives(theta, 1, s);
  const double phi = follower_polar_angle(theta, rotation_), sigma = sense(rotation_);
  const double len = std::hypot(s[1], t), cos_a = side * sigma * s[1] / len, sin_a = side * t / len;
  const Eigen::Vector3d u(std::cos(phi), std::sin(phi), 0.0), tau(-std::sin(phi), std::cos(phi), 0.0);
  return t * u + Eigen::Vector3d(0, 0, z0_ + s[0]) + roller_radius_ * (cos_a * tau + Eigen::Vector3d(0, 0, sin_a));
}

}  // namespace polarform
