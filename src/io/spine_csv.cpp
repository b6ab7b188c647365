#include "src/io/spine_csv.h"

#include <cmath>
#include <vector>

#include "src/error.h"
#include "src/io/csv_text.h"
#include "src/io/text_scan.h"

namespace polarform {

Eigen::Matrix3Xd parse_spine_csv(std::string_view text, const std::string& name) {
  std::vector<Eigen::Vector3d> points;
  bool header = false;
  for_each_data_line(text, name, [&](std::string_view line, const std::string& where) {
    const std::vector<std::string_view> f = comma_fields(line);
    if (!header) {
      if (f.size() != 3 || f[0] != "x" || f[1] != "y" || f[2] != "z")
        throw InputError(where + "header '" + std::string(line) + "': expected 'x,y,z'");
      header = true;
      return;
    }
    if (f.size() != 3)
      throw InputError(where + "expected 3 fields (x,y,z), found " + std::to_string(f.size()));
    Eigen::Vector3d p;
    const char* axis[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
      if (!io_detail::parse_double(f[static_cast<std::size_t>(i)], p[i]) || !std::isfinite(p[i]))
        throw InputError(where + axis[i] + " '" + std::string(f[static_cast<std::size_t>(i)]) +
                         "': expected a finite number");
    if (!points.empty() && p == points.back())
      throw InputError(where + "the point repeats the one before it");
    points.push_back(p);
  });
  if (!header) throw InputError(name + ": no header line; expected 'x,y,z'");
  if (points.size() < 2)
    throw InputError(name + ": " + std::to_string(points.size()) +
                     " spine point(s), expected at least 2");
  Eigen::Matrix3Xd out(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) out.col(static_cast<Eigen::Index>(i)) = points[i];
  return out;
}

Eigen::Matrix3Xd read_spine_csv(const std::filesystem::path& file) {
  return parse_spine_csv(read_text_file(file), file.string());
}

}  // namespace polarform
