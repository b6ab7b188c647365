// Figures (export/figure.h) as report-quality SVG: panels with nice ticks on linear or log axes,
// a light grid, series, reference lines, bands, highlighted points (with their explanation as a
// tooltip) and annotations, and a legend. The output is self-contained, deterministic (same
// figure, same bytes) and embeds in report.html.
#pragma once

#include <filesystem>
#include <string>

#include "export/figure.h"

namespace polarform {

// The SVG document. Throws InputError for settings that cannot be drawn (no panels, an empty or
// non-positive log range, panels that do not fit the height).
std::string svg_document(const Figure& figure);
// Writes svg_document(figure) to path atomically.
void save_svg(const Figure& figure, const std::filesystem::path& path);

}  // namespace polarform
