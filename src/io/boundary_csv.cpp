#include "src/io/boundary_csv.h"

#include <cmath>
#include <vector>

#include "src/error.h"
#include "src/io/csv_text.h"
#include "src/io/text_scan.h"

namespace polarform {

namespace {

constexpr const char* kHeader = "curve,x,y,z";

}  // namespace

BoundaryPolylines parse_boundary_csv(std::string_view text, const std::string& name) {
  std::array<std::vector<Eigen::Vector3d>, 4> points;
  bool header = false;
  int current = -1;  // the curve of the previous row
  for_each_data_line(text, name, [&](std::string_view line, const std::string& where) {
    const std::vector<std::string_view> f = comma_fields(line);
    if (!header) {
      const char* names[4] = {"curve", "x", "y", "z"};
      bool ok = f.size() == 4;
      for (std::size_t i = 0; ok && i < 4; ++i) ok = f[i] == names[i];
      if (!ok)
        throw InputError(where + "header '" + std::string(line) + "': expected '" + kHeader + "'");
      header = true;
      return;
    }
    if (f.size() != 4)
      throw InputError(where + "expected 4 fields (" + kHeader + "), found " +
                       std::to_string(f.size()));
    double c = 0.0;
    if (!io_detail::parse_double(f[0], c) || !(c == 0 || c == 1 || c == 2 || c == 3))
      throw InputError(where + "curve '" + std::string(f[0]) + "': expected 0, 1, 2 or 3");
    const int k = static_cast<int>(c);
    if (k < current)
      throw InputError(where + "curve " + std::to_string(k) + " after curve " +
                       std::to_string(current) +
                       ": the rows of each curve must be together, curves 0 to 3 in loop order");
    if (k > current && !points[static_cast<std::size_t>(k)].empty())
      throw InputError(where + "curve " + std::to_string(k) + " is split");
    current = k;
    Eigen::Vector3d p;
    const char* axis[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
      if (!io_detail::parse_double(f[static_cast<std::size_t>(i + 1)], p[i]) || !std::isfinite(p[i]))
        throw InputError(where + axis[i] + " '" + std::string(f[static_cast<std::size_t>(i + 1)]) +
                         "': expected a finite number");
    points[static_cast<std::size_t>(k)].push_back(p);
  });
  if (!header) throw InputError(name + ": no header line; expected '" + kHeader + "'");
  BoundaryPolylines out;
  for (std::size_t k = 0; k < 4; ++k) {
    if (points[k].size() < 2)
      throw InputError(name + ": curve " + std::to_string(k) + " has " +
                       std::to_string(points[k].size()) +
                       " point(s); a boundary needs four curves of at least 2 points each");
    out.curves[k].resize(3, static_cast<Eigen::Index>(points[k].size()));
    for (std::size_t i = 0; i < points[k].size(); ++i)
      out.curves[k].col(static_cast<Eigen::Index>(i)) = points[k][i];
  }
  return out;
}

BoundaryPolylines read_boundary_csv(const std::filesystem::path& file) {
  return parse_boundary_csv(read_text_file(file), file.string());
}

}  // namespace polarform
