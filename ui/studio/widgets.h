// Small input widgets shared by the panels, all labelled with units: a length in mm, an angle
// stored in radians but edited in degrees, a log-scale slider (tolerances), a combo over named
// choices, and a hover help marker. Each returns true when the value changed this frame.
#pragma once

#include <span>
#include <string_view>

#include "src/units.h"

namespace polarform::studio {

bool input_number(const char* label, double& value, double step = 0.1, const char* format = "%.4g");
bool drag_number(const char* label, double& value, double speed, double min, double max,
                 const char* format);
// Angle in radians, shown and edited in degrees within [min_deg, max_deg].
bool drag_angle(const char* label, double& radians, double min_deg, double max_deg);
bool input_int(const char* label, int& value, int min, int max);
// Logarithmic slider over [min, max] (both > 0), text like "%.3g mm".
bool log_slider(const char* label, double& value, double min, double max, const char* format);
// Combo over `names`; `index` is the selected entry.
bool combo(const char* label, int& index, std::span<const std::string_view> names);
// "(?)" with a tooltip.
void help_marker(const char* text);
// A section heading: some space, the title, a separator.
void section(const char* title);

}  // namespace polarform::studio
