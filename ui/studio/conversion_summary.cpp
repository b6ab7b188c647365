#include "ui/studio/conversion_summary.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

#include "src/units.h"

namespace polarform::studio {

ConversionSummary summarize(const PolarConversion& c) {
  ConversionSummary s;
  s.arcs = static_cast<int>(c.arcs.size());
  s.degree = c.curve.degree();
  s.control_points = c.curve.size();
  s.rational = c.curve.is_rational();
  s.function_exact = c.function_exact;
  s.tolerance = c.tolerance;
  s.max_radial_error = c.max_radial_error;
  s.max_normal_error = c.max_normal_error;
  s.worst_angle = c.worst_angle;
  s.max_tangent_jump = c.max_tangent_jump;
  s.function_error = c.function_error;
  s.synchronization_error = c.synchronization_error;
  return s;
}

std::string ConversionSummary::text() const {
  char buffer[200];
  std::snprintf(buffer, sizeof buffer,
                "%d arcs, degree %d, %d control points, max radial error %.3g µm %s %.3g µm", arcs,
                degree, control_points, max_radial_error * 1e3,
                max_radial_error <= tolerance ? "≤" : ">", tolerance * 1e3);
  return buffer;
}

std::string ConversionSummary::numbers() const {
  std::ostringstream out;
  out.precision(10);
  out << "arcs=" << arcs << "\ndegree=" << degree << "\ncontrol_points=" << control_points
      << "\ntolerance_mm=" << tolerance << "\nmax_radial_error_mm=" << max_radial_error
      << "\nmax_normal_error_mm=" << max_normal_error << "\nworst_angle_deg="
      << std::remainder(worst_angle, 2 * std::numbers::pi) * kDegreesPerRadian << "\n";
  return out.str();
}

}  // namespace polarform::studio
