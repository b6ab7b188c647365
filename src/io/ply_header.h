// The header of a PLY file (Turk's polygon file format): storage format, and the elements with
// their counts and typed properties, scalar or list, in file order. Data starts at data_offset.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace polarform {

enum class PlyStorage { ascii, binary_little_endian, binary_big_endian };

enum class PlyType { int8, uint8, int16, uint16, int32, uint32, float32, float64 };

std::size_t ply_type_size(PlyType type);
bool ply_type_is_integer(PlyType type);

struct PlyProperty {
  std::string name;
  PlyType type{};  // the scalar type, or the item type of a list
  bool is_list = false;
  PlyType count_type{};  // the type of a list's leading count (an integer type)
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  PlyStorage storage = PlyStorage::ascii;
  std::vector<PlyElement> elements;
  std::size_t data_offset = 0;   // byte just past the end_header line
  std::size_t header_lines = 0;  // lines in the header: the first data line is header_lines + 1
};

// Parses the header of an in-memory PLY file. Throws InputError naming `name` and the header
// line for a missing magic, unsupported format, unknown type or keyword, or no end_header.
PlyHeader parse_ply_header(std::string_view bytes, std::string_view name);

}  // namespace polarform
