// ASCII PLY element data: one record per line (blank lines are skipped), values separated by
// blanks, a list as its count followed by that many items. Vertex records are checked value by
// value; records of other elements are only counted.
#include <cstdint>
#include <string>

#include "src/io/ply_data.h"
#include "src/io/text_scan.h"

namespace polarform::io_detail {

namespace {

// Parses x, y, z out of one vertex line; on failure `what` says what was expected.
bool parse_vertex(std::string_view line, const PlyElement& vertex, const PlyVertexLayout& layout,
                  double xyz[3], std::string& what) {
  std::string_view rest = line;
  for (std::size_t k = 0; k < vertex.properties.size(); ++k) {
    const PlyProperty& property = vertex.properties[k];
    const std::string_view token = next_token(rest);
    if (token.empty()) {
      what = "expected a value for property '" + property.name + "', found the end of the line";
      return false;
    }
    if (property.is_list) {
      std::uint64_t count;
      if (!parse_count(token, count)) {
        what = "invalid list count " + quoted(token) + " for property '" + property.name +
               "': expected a non-negative integer";
        return false;
      }
      for (std::uint64_t j = 0; j < count; ++j)
        if (next_token(rest).empty()) {
          what = "list '" + property.name + "' declares " + std::to_string(count) +
                 " items but the line ends after " + std::to_string(j);
          return false;
        }
      continue;
    }
    for (int c = 0; c < 3; ++c)
      if (k == layout.xyz[c] && !parse_double(token, xyz[c])) {
        what = "invalid number " + quoted(token) + " for property '" + property.name +
               "': expected a decimal number";
        return false;
      }
  }
  if (!next_token(rest).empty()) {
    what = "more values than the " + std::to_string(vertex.properties.size()) +
           " properties of element 'vertex'";
    return false;
  }
  return true;
}

class AsciiReader {
 public:
  AsciiReader(std::string_view bytes, const PlyHeader& header, CloudBuilder& builder)
      : lines_(bytes, header.data_offset, header.header_lines), builder_(builder) {}

  void skip(const PlyElement& element) {
    std::string_view line;
    for (std::uint64_t r = 0; r < element.count; ++r) {
      if (!next_record(line))
        builder_.fail(here(), "file ends after " + std::to_string(r) + " of the " +
                                  std::to_string(element.count) + " records of element '" +
                                  element.name + "': the file is truncated or the count is wrong");
      builder_.progress(lines_.offset());
    }
  }

  void read_vertices(const PlyElement& vertex, const PlyVertexLayout& layout) {
    std::string_view line;
    std::string what;
    for (std::uint64_t i = 0; i < vertex.count; ++i) {
      if (!next_record(line))
        builder_.fail(here(), "file ends after " + std::to_string(i) + " of the " +
                                  std::to_string(vertex.count) +
                                  " vertices: the file is truncated or the vertex count is wrong");
      const auto where = [&] { return here() + " (vertex " + std::to_string(i) + ")"; };
      double xyz[3];
      if (parse_vertex(line, vertex, layout, xyz, what))
        builder_.add(xyz[0], xyz[1], xyz[2], where);
      else
        builder_.reject(where(), what);
      builder_.progress(lines_.offset());
    }
  }

 private:
  // The next line that is not blank.
  bool next_record(std::string_view& line) {
    while (lines_.next(line))
      if (!trim(line).empty()) return true;
    return false;
  }

  std::string here() const { return "line " + std::to_string(lines_.line_number()); }

  LineCursor lines_;
  CloudBuilder& builder_;
};

}  // namespace

void read_ply_ascii(std::string_view bytes, const PlyHeader& header, const PlyVertexLayout& layout,
                    CloudBuilder& builder) {
  AsciiReader reader(bytes, header, builder);
  for (std::size_t e = 0; e < header.elements.size(); ++e)
    if (e == layout.element)
      reader.read_vertices(header.elements[e], layout);
    else
      reader.skip(header.elements[e]);
}

}  // namespace polarform::io_detail
