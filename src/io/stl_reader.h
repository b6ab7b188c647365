// STL meshes, ascii and binary: every triangle vertex becomes a point (vertices shared between
// triangles repeat, which the fitters tolerate). Binary is recognised by its size, 84 + 50·n bytes
// for the n triangles it declares -- even when its 80-byte header starts with "solid".
#pragma once

#include <string_view>

#include "src/io/point_cloud.h"

namespace polarform {

PointCloud parse_stl(std::string_view bytes, std::string_view name,
                     const ReadOptions& options = {});

// True if the bytes are exactly 84 + 50·n long for the n triangles declared at byte 80.
bool has_binary_stl_size(std::string_view bytes);

}  // namespace polarform
