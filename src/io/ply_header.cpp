#include "src/io/ply_header.h"

#include "src/error.h"
#include "src/io/text_scan.h"

namespace polarform {

using namespace io_detail;

namespace {

struct TypeName {
  std::string_view name;
  PlyType type;
};

constexpr TypeName kTypeNames[] = {
    {"char", PlyType::int8},      {"int8", PlyType::int8},       {"uchar", PlyType::uint8},
    {"uint8", PlyType::uint8},    {"short", PlyType::int16},     {"int16", PlyType::int16},
    {"ushort", PlyType::uint16},  {"uint16", PlyType::uint16},   {"int", PlyType::int32},
    {"int32", PlyType::int32},    {"uint", PlyType::uint32},     {"uint32", PlyType::uint32},
    {"float", PlyType::float32},  {"float32", PlyType::float32}, {"double", PlyType::float64},
    {"float64", PlyType::float64}};

bool parse_type(std::string_view token, PlyType& type) {
  for (const TypeName& t : kTypeNames)
    if (t.name == token) {
      type = t.type;
      return true;
    }
  return false;
}

}  // namespace

std::size_t ply_type_size(PlyType type) {
  switch (type) {
    case PlyType::int8:
    case PlyType::uint8:
      return 1;
    case PlyType::int16:
    case PlyType::uint16:
      return 2;
    case PlyType::int32:
    case PlyType::uint32:
    case PlyType::float32:
      return 4;
    case PlyType::float64:
      return 8;
  }
  return 0;
}

bool ply_type_is_integer(PlyType type) {
  return type != PlyType::float32 && type != PlyType::float64;
}

PlyHeader parse_ply_header(std::string_view bytes, std::string_view name) {
  LineCursor lines(bytes);
  const auto fail = [&](const std::string& what) {
    throw InputError(std::string(name) + ": line " + std::to_string(lines.line_number()) + ": " +
                     what);
  };
  std::string_view line;
  if (!lines.next(line) || trim(line) != "ply")
    fail("expected 'ply' as the first line of a PLY file");
  PlyHeader header{};
  bool have_format = false;
  for (;;) {
    if (!lines.next(line))
      throw InputError(std::string(name) + ": PLY header has no 'end_header' line");
    std::string_view rest = line;
    const std::string_view keyword = next_token(rest);
    if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") break;
    if (keyword == "format") {
      const std::string_view storage = next_token(rest);
      if (storage == "ascii")
        header.storage = PlyStorage::ascii;
      else if (storage == "binary_little_endian")
        header.storage = PlyStorage::binary_little_endian;
      else if (storage == "binary_big_endian")
        header.storage = PlyStorage::binary_big_endian;
      else
        fail("unsupported PLY format " + quoted(storage) +
             ": expected ascii, binary_little_endian or binary_big_endian");
      if (next_token(rest).empty())
        fail("expected a version after the format, as in 'format ascii 1.0'");
      have_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      element.name = next_token(rest);
      if (element.name.empty() || !parse_count(next_token(rest), element.count))
        fail("expected 'element <name> <count>' with a non-negative integer count");
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) fail("'property' before any 'element'");
      PlyProperty property;
      std::string_view type = next_token(rest);
      if (type == "list") {
        property.is_list = true;
        const std::string_view count_type = next_token(rest);
        if (!parse_type(count_type, property.count_type) ||
            !ply_type_is_integer(property.count_type))
          fail("list count type " + quoted(count_type) +
               ": expected an integer type such as uchar or int");
        type = next_token(rest);
      }
      if (!parse_type(type, property.type))
        fail("unknown property type " + quoted(type) +
             ": expected char, uchar, short, ushort, int, uint, float, double (or int8 ... "
             "float64)");
      property.name = next_token(rest);
      if (property.name.empty()) fail("expected a property name after its type");
      header.elements.back().properties.push_back(std::move(property));
    } else {
      fail("unknown PLY header keyword " + quoted(keyword) +
           ": expected format, element, property, comment, obj_info or end_header");
    }
  }
  if (!have_format) fail("PLY header has no 'format' line");
  header.data_offset = lines.offset();
  header.header_lines = lines.line_number();
  return header;
}

}  // namespace polarform
