// The X3D scene of a visualised field (Bae 2002, §5.3): the NURBS surface S = (s·F + d)·B of the
// X3D writer, put in a Switch behind a tessellation of the same surface whose vertices are
// coloured by the value F there (IndexedFaceSet + Color), and the control net as points coloured
// by the value each control point carries (PointSet + Color). Colours follow viridis over the
// control values' range.
#pragma once

#include <string>

#include "src/fit/scalar_field_surface.h"

namespace polarform {

// The tessellation (src/nurbs/tessellation.h) takes rows equal steps in u and cols in v, plus
// every distinct interior knot (both >= 1).
std::string field_x3d(const ScalarFieldSurface& field, const std::string& title, int rows = 64,
                      int cols = 128);

}  // namespace polarform
