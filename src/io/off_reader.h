// Object File Format (Geomview OFF, ascii): an optional keyword [ST][C][N][4][n]OFF, an Ndim line
// for nOFF, the counts "NVertices NFaces NEdges", then one vertex per line. x y z are the first
// three components; with the 4 prefix the last component is homogeneous and divides them. Normals,
// colours, texture coordinates and faces are ignored. Binary OFF ("OFF BINARY") is rejected.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

#include "src/io/point_cloud.h"

namespace polarform {

PointCloud parse_off(std::string_view bytes, std::string_view name,
                     const ReadOptions& options = {});

struct OffKeyword {
  std::size_t length;   // characters of the keyword
  bool homogeneous;     // "4" prefix: one more, homogeneous, component per vertex
  bool dimension_line;  // "n" prefix: the vertex dimension follows the keyword
};

// The OFF keyword at the start of `text`, if there is one. It may be followed directly by the
// counts, as in the "OFF490 518 0" of some published data sets.
std::optional<OffKeyword> match_off_keyword(std::string_view text);

}  // namespace polarform
