// The two halves of the PLY reader behind parse_ply: reading the element data of a parsed header,
// in ascii (one record per line) or binary (either byte order), into a CloudBuilder.
#pragma once

#include <cstddef>
#include <string_view>

#include "src/io/cloud_builder.h"
#include "src/io/ply_header.h"

namespace polarform::io_detail {

// Where the coordinates live: the index of element "vertex" and of its x, y, z properties.
struct PlyVertexLayout {
  std::size_t element;
  std::size_t xyz[3];
};

void read_ply_ascii(std::string_view bytes, const PlyHeader& header, const PlyVertexLayout& layout,
                    CloudBuilder& builder);

void read_ply_binary(std::string_view bytes, const PlyHeader& header, const PlyVertexLayout& layout,
                     CloudBuilder& builder);

}  // namespace polarform::io_detail
