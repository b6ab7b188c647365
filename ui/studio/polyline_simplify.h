// Drawing fewer vertices for the same picture: a pixel polyline reduced to the points where it
// bends by more than a fraction of a pixel (Douglas–Peucker simplification: every dropped point
// lies within `tolerance` pixels of the chord that replaces it). Software OpenGL (Mesa llvmpipe)
// pays per triangle, and smooth or flat stretches of the motion curves need only a few.
#pragma once

#include "export/polyline_path.h"

namespace polarform::studio {

Polyline simplify_polyline(const Polyline& points, double tolerance = 0.3);

}  // namespace polarform::studio
