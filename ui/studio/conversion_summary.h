// What a user reads about a NURBS conversion, in one place for the cam and vessel workspaces:
// arcs, degree, control points and the measured errors against the tolerance, as display text
// and as the "name=value" lines of the headless modes.
#pragma once

#include <string>

#include "designers/convert/polar_conversion.h"

namespace polarform::studio {

struct ConversionSummary {
  int arcs = 0, degree = 0, control_points = 0;
  bool rational = false, function_exact = false;
  double tolerance = 0.0, max_radial_error = 0.0, max_normal_error = 0.0, worst_angle = 0.0;
  double max_tangent_jump = 0.0, function_error = 0.0, synchronization_error = 0.0;

  // "12 arcs, degree 9, 85 control points, max radial error 0.81 µm ≤ 1 µm"
  std::string text() const;
  std::string numbers() const;
};

ConversionSummary summarize(const PolarConversion& conversion);

}  // namespace polarform::studio
