// The converter's figures in a job's report.json — tolerance, arcs, degree, control points,
// measured errors, G1 check, base, error budget, the control points after each conversion step
// and the arc list — under the field names that
// docs/file-formats.md fixes for the cam and vessel reports alike.
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>

#include "designers/convert/polar_conversion.h"

namespace polarform {

// Appends the fields to j, in report order. degree, control_points and knot_count describe the
// curve the job exports (the converted profile, or the track built from it). Angles in degrees
// in [0, 360).
void add_conversion_fields(nlohmann::ordered_json& j, const PolarConversion& c, int degree,
                           int control_points, std::size_t knot_count);

}  // namespace polarform
