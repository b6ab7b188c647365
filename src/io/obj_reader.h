// Wavefront OBJ: the geometric vertices ("v x y z [w]" or "v x y z r g b") become the points;
// every other statement (vn, vt, f, o, g, usemtl, ...) and '#' comments are ignored.
#pragma once

#include <string_view>

#include "src/io/point_cloud.h"

namespace polarform {

PointCloud parse_obj(std::string_view bytes, std::string_view name,
                     const ReadOptions& options = {});

}  // namespace polarform
