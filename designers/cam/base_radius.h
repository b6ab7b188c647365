// The smallest base radius Rb for which a plate cam meets a pressure-angle limit and has no
// undercut (optionally: a minimum convex contour radius of curvature), by bisection on Rb over
// the analyses of cam_analysis.h. Norton, Cam Design and Manufacturing Handbook (cam sizing): pressure angle and
// curvature improve as Rb grows, which the bisection relies on. The achieved values are reported.
#pragma once

#include <numbers>
#include <span>

#include "designers/cam/cam_analysis.h"

namespace polarform {

struct BaseRadiusRequirements {
  double max_pressure_angle = std::numbers::pi / 6;  // rad; knife-edge and roller only
  // Smallest allowed convex radius of curvature of the contour, mm; 0 asks only for no undercut.
  double min_convex_radius = 0.0;
};

struct BaseRadiusResult {
  double base_radius = 0.0;                 // mm, within a relative 1e-9 of the smallest feasible
  Extremum max_pressure_angle;              // achieved at base_radius
  Extremum min_convex_contour_radius;       // achieved at base_radius
  double min_contour_speed = 0.0;           // > 0: no undercut
  int analyses = 0;                         // cam analyses run by the search
};

// Throws InputError on invalid requirements; NumericalError if no base radius up to 1e6 times the
// stroke satisfies them.
BaseRadiusResult minimum_base_radius(const CamProgram& program, const Follower& follower, Rotation rotation,
                                     const BaseRadiusRequirements& requirements, std::span<const double> thetas);

}  // namespace polarform
