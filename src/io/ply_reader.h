// PLY point clouds and meshes (ascii, binary_little_endian, binary_big_endian): reads x, y, z
// (float or double) of element "vertex"; every other property -- any type, lists included -- and
// every other element, before or after the vertices, is skipped. The elements after the vertices
// are still walked, so a truncated file or a wrong count in the header is reported.
#pragma once

#include <string_view>

#include "src/io/point_cloud.h"

namespace polarform {

PointCloud parse_ply(std::string_view bytes, std::string_view name,
                     const ReadOptions& options = {});

}  // namespace polarform
