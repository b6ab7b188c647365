#include "src/io/spine_csv.h"

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

std::vector<std::string_view> comma_fields(std::string_view line) {
  std::vector<std::string_view> out;
  while (true) {
    const std::size_t c = line.find(',');
    out.push_back(trim(line.substr(0, c)));
    if (c == std::string_view::npos) return out;
    line.remove_prefix(c + 1);
  }
}

}  // namespace

Eigen::Matrix3Xd parse_spine_csv(std::string_view text, const std::string& name) {
  std::vector<Eigen::Vector3d> points;
  std::size_t line_no = 0;
  bool header = false;
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
      if (f.size() != 3 || f[0] != "x" || f[1] != "y" || f[2] != "z")
        throw InputError(where + "header '" + std::string(line) + "': expected 'x,y,z'");
      header = true;
      continue;
    }
    if (f.size() != 3)
      throw InputError(where + "expected 3 fields (x,y,z), found " + std::to_string(f.size()));
    Eigen::Vector3d p;
    const char* axis[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
      if (!parse_double(f[static_cast<std::size_t>(i)], p[i]) || !std::isfinite(p[i]))
        throw InputError(where + axis[i] + " '" + std::string(f[static_cast<std::size_t>(i)]) +
                         "': expected a finite number");
    if (!points.empty() && p == points.back())
      throw InputError(where + "the point repeats the one before it");
    points.push_back(p);
  }
  if (!header) throw InputError(name + ": no header line; expected 'x,y,z'");
  if (points.size() < 2)
    throw InputError(name + ": " + std::to_string(points.size()) +
                     " spine point(s), expected at least 2");
  Eigen::Matrix3Xd out(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) out.col(static_cast<Eigen::Index>(i)) = points[i];
  return out;
}

Eigen::Matrix3Xd read_spine_csv(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": cannot open file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_spine_csv(text.str(), file.string());
}

}  // namespace polarform
