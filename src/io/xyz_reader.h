// Delimited-text point clouds (.xyz, .csv, .txt, .asc, .pts): one point per line, x y z in the
// first three fields, separated by blanks or by commas (blanks around a comma allowed). Further
// columns are ignored, '#' starts a comment, and text lines before the first data line are skipped
// (a column header, or the lone point count that opens a .pts file).
#pragma once

#include <string_view>

#include "src/io/point_cloud.h"

namespace polarform {

PointCloud parse_xyz(std::string_view bytes, std::string_view name,
                     const ReadOptions& options = {});

}  // namespace polarform
