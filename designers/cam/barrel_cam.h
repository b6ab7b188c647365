// BarrelCam: a cylindrical (barrel) cam whose groove drives a translating follower parallel to the
// cam axis through a roller with a radial axis. The track centre line lies on the pitch cylinder
// of radius Rc: z = z0 + s(θ) at cam-frame angle φ = π/2 - σθ (cam_frame.h). Chen, Mechanics and
// Design of Cam Mechanisms (cylindrical cams); Norton, Cam Design and Manufacturing Handbook.
// Cam axis = z axis of the cam frame; the follower sits on the +y side of the fixed frame.
#pragma once

#include <Eigen/Core>

#include "designers/cam/cam_frame.h"
#include "designers/cam/cam_program.h"
#include "designers/convert/polar_function.h"

namespace polarform {

class BarrelCam {
 public:
  // Throws InputError unless Rc > 0, 0 < Rr < Rc and z0 is finite.
  BarrelCam(CamProgram program, double pitch_radius, double z0, double roller_radius,
            Rotation rotation = Rotation::CounterClockwise);

  const CamProgram& program() const { return program_; }
  double pitch_radius() const { return pitch_radius_; }
  double z0() const { return z0_; }
  double roller_radius() const { return roller_radius_; }
  Rotation rotation() const { return rotation_; }

  // The track height z(φ) = z0 + s(θ(φ)) as a function of the cam-frame angle φ: the converter
  // takes x, y from a base circle of radius Rc and z from this; exact B-spline when the program is
  // polynomial.
  PolarFunction track_height() const;
  // Track centre point on the pitch cylinder (cam frame), θ-derivatives 0..d (d <= 3).
  void track_point(double theta, int d, Eigen::Vector3d* out) const;
  // Unit direction of the roller axis (radial, pointing away from the cam axis), cam frame.
  Eigen::Vector3d roller_axis(double theta) const;
  // Pressure angle at distance t from the cam axis along the roller axis: atan(s'/t), positive
  // during a rise (the groove's lead angle grows towards the axis).
  double pressure_angle(double theta, double t) const;
  // Contact point of a cylindrical roller on a groove wall at distance t from the cam axis along
  // the roller axis: side = +1 for the wall on the +z side of the track, -1 for the other. Exact
  // envelope of the roller surface: with u radial, τ tangential and k axial, the point is
  // t u + z k + Rr (cos α τ + sin α k) with (cos α, sin α) = side (σ s', t)/sqrt(s'² + t²).
  Eigen::Vector3d groove_wall_point(double theta, double t, int side) const;

 private:
  CamProgram program_;
  double pitch_radius_;
  double z0_;
  double roller_radius_;
  Rotation rotation_;
};

}  // namespace polarform
