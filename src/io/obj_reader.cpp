#include "src/io/obj_reader.h"

#include <string>

#include "src/io/cloud_builder.h"
#include "src/io/text_scan.h"

namespace polarform {

using namespace io_detail;

PointCloud parse_obj(std::string_view bytes, std::string_view name, const ReadOptions& options) {
  CloudBuilder builder(name, bytes.size(), options);
  builder.reserve(count_keyword_lines(bytes, "v"));
  LineCursor lines(bytes);
  std::string what;
  for (std::string_view line; lines.next(line);) {
    builder.progress(lines.offset());
    std::string_view rest = strip_comment(line);
    if (next_token(rest) != "v") continue;
    const auto where = [&] { return "line " + std::to_string(lines.line_number()); };
    double xyz[3];
    if (parse_coordinates(rest, xyz, 3, what))
      builder.add(xyz[0], xyz[1], xyz[2], where);
    else
      builder.reject(where(), what);
  }
  return builder.finish();
}

}  // namespace polarform
