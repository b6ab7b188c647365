// How the cam workspace shows a design, independent of the design itself (not undone, not saved
// with the project): the pressure-angle limit that colours the profile and sizes the base radius,
// the units of the motion plots, the profile view's toggles and the follower's animation angle.
#pragma once

#include "src/units.h"

namespace polarform::studio {

enum class MotionUnits { per_radian, time };

struct CamViewSettings {
  double pressure_angle_limit = 30.0 * kRadiansPerDegree;  // rad
  MotionUnits units = MotionUnits::per_radian;
  bool show_pitch = true;
  bool show_base_circle = true;
  bool show_control_polygon = false;
  bool show_curvature_comb = false;
  bool show_pressure_colour = true;
  bool show_follower = true;
  bool cam_turns = true;  // fixed frame: the cam turns under the follower
  bool animate = false;
  double follower_angle = 0.0;    // cam angle θ of the drawn follower, rad
  double animation_period = 4.0;  // seconds per revolution
  double comb_scale = 0.5;  // comb length per unit curvature, as a fraction of the base radius x Rb
};

}  // namespace polarform::studio
