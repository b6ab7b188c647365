// Marker symbols for scatter series and legend swatches, as SVG path data so that all markers of
// a series are one <path>. Shapes cycle circle, square, triangle, diamond, so series stay
// distinguishable in greyscale and for colour-blind readers.
#pragma once

#include <string>

#include "export/polyline_path.h"

namespace polarform {

enum class MarkerShape { circle, square, triangle, diamond };

// The shape for the index-th marker-drawing series of a plot.
MarkerShape marker_shape(int index);

// Path data of one marker centred at c with "radius" r (half the width of the symbol).
std::string marker_path(MarkerShape shape, PixelPoint c, double r);

}  // namespace polarform
