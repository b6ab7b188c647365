// Estimated width of a line of text in a sans-serif font, from per-character advance widths
// close to DejaVu Sans (slightly generous for Helvetica/Arial). It lets the plot layout keep tick
// labels and legends clear of each other without a font engine.
#pragma once

#include <string_view>

namespace polarform {

// Width in pixels of UTF-8 text set at font_size pixels.
double text_width(std::string_view utf8, double font_size);

}  // namespace polarform
