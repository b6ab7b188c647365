#include "src/io/ply_reader.h"

#include <string>

#include "src/io/ply_data.h"

namespace polarform {

using namespace io_detail;

namespace {

PlyVertexLayout vertex_layout(const PlyHeader& header, const CloudBuilder& builder) {
  static constexpr const char* axis[] = {"x", "y", "z"};
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    if (element.name != "vertex") continue;
    PlyVertexLayout layout{e, {}};
    for (int k = 0; k < 3; ++k) {
      std::size_t p = 0;
      while (p < element.properties.size() && element.properties[p].name != axis[k]) ++p;
      if (p == element.properties.size())
        builder.fail("PLY header",
                     std::string("element 'vertex' has no property '") + axis[k] + "'");
      const PlyProperty& property = element.properties[p];
      if (property.is_list || ply_type_is_integer(property.type))
        builder.fail("PLY header", std::string("vertex property '") + axis[k] +
                                       "' must be a float or double scalar");
      layout.xyz[k] = p;
    }
    return layout;
  }
  builder.fail("PLY header", "no 'vertex' element");
}

}  // namespace

PointCloud parse_ply(std::string_view bytes, std::string_view name, const ReadOptions& options) {
  const PlyHeader header = parse_ply_header(bytes, name);
  CloudBuilder builder(name, bytes.size(), options);
  const PlyVertexLayout layout = vertex_layout(header, builder);
  builder.reserve(header.elements[layout.element].count);
  if (header.storage == PlyStorage::ascii)
    read_ply_ascii(bytes, header, layout, builder);
  else
    read_ply_binary(bytes, header, layout, builder);
  return builder.finish();
}

}  // namespace polarform
