#include "jobs/project/motion_table_csv.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>
#include <vector>

#include "src/error.h"
#include "src/io/text_scan.h"
#include "src/number_text.h"
#include "src/units.h"

namespace polarform {

namespace {

using io_detail::quoted;
using io_detail::strip_comment;
using io_detail::trim;

struct Columns {
  bool absolute = false;   // theta, s
  std::vector<double> a;   // x or θ
  std::vector<double> b;   // S or s
  std::vector<int> lines;  // the line of each row
};

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return out;
}

// The two comma-separated fields of a line; false unless there are exactly two.
bool split(std::string_view line, std::string_view& first, std::string_view& second) {
  const std::size_t comma = line.find(',');
  if (comma == std::string_view::npos || line.find(',', comma + 1) != std::string_view::npos)
    return false;
  first = trim(line.substr(0, comma));
  second = trim(line.substr(comma + 1));
  return true;
}

Columns read_columns(std::string_view text, const std::string& file) {
  Columns c;
  bool header = false;
  const char* names[2] = {"x", "S"};
  int line = 0;
  while (!text.empty()) {
    const std::size_t eol = text.find('\n');
    const std::string_view raw = text.substr(0, eol);
    text.remove_prefix(eol == std::string_view::npos ? text.size() : eol + 1);
    ++line;
    const std::string_view content = strip_comment(raw);
    if (content.empty()) continue;
    const std::string where = file + ":" + std::to_string(line) + ": ";
    std::string_view first, second;
    if (!split(content, first, second))
      throw InputError(where + "expected two comma-separated fields, got " + quoted(content));
    if (!header) {
      const std::string f = lower(first), s = lower(second);
      if (s != "s" || (f != "x" && f != "theta"))
        throw InputError(
            where + "expected the header 'x,S' (normalised) or 'theta,s' (degrees, length), got " +
            quoted(content));
      header = true;
      c.absolute = f == "theta";
      if (c.absolute) names[0] = "theta", names[1] = "s";
      continue;
    }
    double v[2];
    for (int k = 0; k < 2; ++k)
      if (!io_detail::parse_double(k == 0 ? first : second, v[k]) || !std::isfinite(v[k]))
        throw InputError(where + names[k] + ": expected a finite number, got " +
                         quoted(k == 0 ? first : second));
    if (c.a.size() == kMaxTableRows)
      throw InputError(where + "more than " + std::to_string(kMaxTableRows) + " rows");
    c.a.push_back(v[0]);
    c.b.push_back(v[1]);
    c.lines.push_back(line);
  }
  if (!header) throw InputError(file + ": empty; expected the header 'x,S' or 'theta,s' and rows");
  return c;
}

// An absolute table's rows as fractions of its span, checked against the segment.
void normalise(Columns& c, const std::string& file, const TableSegment& seg) {
  const std::size_t n = c.a.size();
  if (n < 2) return;  // too few rows: motion_table_fault says so
  const auto at = [&](std::size_t row) { return file + ":" + std::to_string(c.lines[row]) + ": "; };
  for (const auto& [row, angle, name] :
       {std::tuple{std::size_t{0}, seg.start, "start"}, std::tuple{n - 1, seg.end, "end"}})
    if (std::abs(c.a[row] - angle * kDegreesPerRadian) > 1e-6)
      throw InputError(at(row) + "theta = " + number_text(c.a[row]) + ", expected the segment's " +
                       name + " angle " + degrees_text(angle));
  const double span = c.b.back() - c.b.front(), lift = seg.rise ? seg.lift : -seg.lift;
  if (std::abs(span - lift) > 1e-6 * seg.lift)
    throw InputError(at(n - 1) + "s = " + number_text(c.b.back()) + ", expected the first row's " +
                     number_text(c.b.front()) + (seg.rise ? " + " : " − ") + "the lift " +
                     number_text(seg.lift));
  const double a0 = c.a.front(), da = c.a.back() - a0, b0 = c.b.front();
  for (std::size_t i = 0; i < n; ++i) {
    c.a[i] = i + 1 == n ? 1.0 : (c.a[i] - a0) / da;
    c.b[i] = i + 1 == n ? 1.0 : (c.b[i] - b0) / span;
  }
}

}  // namespace

MotionTable parse_motion_table(std::string_view text, const std::string& file,
                               const TableSegment& segment, TableEnds ends) {
  Columns c = read_columns(text, file);
  if (c.absolute) normalise(c, file, segment);
  MotionTable t{file, std::move(c.a), std::move(c.b), ends};
  if (const auto fault = motion_table_fault(t)) {
    if (fault->field == "rows")
      throw InputError(file + ": " + std::to_string(t.x.size()) + " rows, expected " +
                       fault->expected);
    const char* field = !c.absolute ? fault->field.c_str() : fault->field == "x" ? "theta" : "s";
    throw InputError(file + ":" + std::to_string(c.lines[fault->row]) + ": " + field +
                     ": expected " + fault->expected +
                     (c.absolute ? " (normalised by the first and last rows)" : ""));
  }
  return t;
}

MotionTable read_motion_table(const std::string& project_file, const std::string& name,
                              const TableSegment& segment, TableEnds ends) {
  const std::filesystem::path path = std::filesystem::path(project_file).parent_path() / name;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string() + ": no such file (motion table named by " + project_file + ")");
  if (std::filesystem::file_size(path, ec) > kMaxTableBytes)
    throw InputError(path.string() + ": larger than " + std::to_string(kMaxTableBytes >> 20) +
                     " MB; expected a motion table of at most " + std::to_string(kMaxTableRows) +
                     " rows");
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  MotionTable t = parse_motion_table(text.str(), path.string(), segment, ends);
  t.file = name;
  return t;
}

}  // namespace polarform
