#include "src/io/boundary_csv.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "src/error.h"
#include "src/io/text_scan.h"

namespace polarform {

namespace {

using io_detail::parse_double;
using io_detail::strip_comment;
using io_detail::trim;

// The comma-separated fields of a line, blanks around them trimmed.
std::vector<std::string_view> comma_fields(std::string_view line) {
  std::vector<std::string_view> out;
  while (true) {
    const std::size_t c = line.find(',');
    out.push_back(trim(line.substr(0, c)));
    if (c == std::string_view::npos) return out;
    line.remove_prefix(c + 1);
  }
}

constexpr const char* kHeader = "curve,x,y,z";

}  // namespace

BoundaryPolylines parse_boundary_csv(std::string_view text, const std::string& name) {
  std::array<std::vector<Eigen::Vector3d>, 4> points;
  std::size_t line_no = 0;
  bool header = false;
  int current = -1;  // the curve of the previous row
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    std::string_view line = text.substr(0, nl);
    text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
    ++line_no;
    if (line_no == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);
    line = strip_comment(line);
    if (line.empty()) continue;
    const std::string where = name + ":" + std::to_string(line_no) + ": ";
    const std::vector<std::string_view> f = comma_fields(line);
    if (!header) {
      const char* names[4] = {"curve", "x", "y", "z"};
      bool ok = f.size() == 4;
      for (std::size_t i = 0; ok && i < 4; ++i) ok = f[i] == names[i];
      if (!ok)
        throw InputError(where + "header '" + std::string(line) + "': expected '" + kHeader + "'");
      header = true;
      continue;
    }
    if (f.size() != 4)
      throw InputError(where + "expected 4 fields (" + kHeader + "), found " +
                       std::to_string(f.size()));
    double c = 0.0;
    if (!parse_double(f[0], c) || !(c == 0 || c == 1 || c == 2 || c == 3))
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
      if (!parse_double(f[static_cast<std::size_t>(i + 1)], p[i]) || !std::isfinite(p[i]))
        throw InputError(where + axis[i] + " '" + std::string(f[static_cast<std::size_t>(i + 1)]) +
                         "': expected a finite number");
    points[static_cast<std::size_t>(k)].push_back(p);
  }
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
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_boundary_csv(text.str(), file.string());
}

}  // namespace polarform
