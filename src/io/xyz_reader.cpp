#include "src/io/xyz_reader.h"

#include <string>

#include "src/io/cloud_builder.h"
#include "src/io/text_scan.h"

namespace polarform {

using namespace io_detail;

namespace {

bool is_field_end(char c) { return is_blank(c) || c == ','; }

std::string_view field_at(const char* p, const char* end) {
  const char* e = p;
  while (e < end && !is_field_end(*e)) ++e;
  return {p, static_cast<std::size_t>(e - p)};
}

bool starts_like_number(char c) {
  return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.';
}

// Before the first data line, a line is a header if its first field is text ("x", "X,Y,Z", but
// not "1.0abc", a bad number, nor "nan", a bad value) or a lone integer (the count of a .pts file).
bool is_header(std::string_view line) {
  const std::string_view first = field_at(line.data(), line.data() + line.size());
  double value;
  if (parse_double(first, value)) {
    std::uint64_t count;
    return first.size() == line.size() && parse_count(first, count);
  }
  return !first.empty() && !starts_like_number(first.front());
}

// Parses x y z from a trimmed, comment-free data line. Fields are separated by blanks, or by
// commas if one follows the first field; on failure `what` says what was expected.
bool parse_fields(std::string_view line, double xyz[3], std::string& what) {
  static constexpr const char* axis[] = {"x", "y", "z"};
  const char* p = line.data();
  const char* end = p + line.size();
  bool commas = false;
  for (int i = 0; i < 3; ++i) {
    if (i > 0) {
      p = skip_blanks(p, end);
      if (p < end && *p == ',') {
        if (i == 1) commas = true;
        if (!commas) {
          what = "unexpected ',' after y: separate the fields by blanks or by commas, not both";
          return false;
        }
        p = skip_blanks(p + 1, end);
      } else if (commas && p < end) {
        what = "expected ',' before " + std::string(axis[i]) + ", found " +
               quoted(field_at(p, end)) + " (decimal commas are not supported)";
        return false;
      }
    }
    if (p == end) {
      what = "expected 3 coordinates x y z, found " + std::to_string(i);
      return false;
    }
    const char* next = parse_double_prefix(p, end, xyz[i]);
    if (!next || (next < end && !is_field_end(*next))) {
      what = "invalid number " + quoted(field_at(p, end)) + ": expected " + axis[i] +
             " as a decimal number";
      return false;
    }
    p = next;
  }
  return true;
}

}  // namespace

PointCloud parse_xyz(std::string_view bytes, std::string_view name, const ReadOptions& options) {
  CloudBuilder builder(name, bytes.size(), options);
  builder.reserve(count_lines(bytes));
  const std::size_t bom = bytes.starts_with("\xEF\xBB\xBF") ? 3 : 0;
  LineCursor lines(bytes, bom);
  bool data_started = false;
  std::string what;
  for (std::string_view raw; lines.next(raw);) {
    const std::string_view line = strip_comment(raw);
    if (line.empty()) continue;
    if (!data_started && is_header(line)) continue;
    data_started = true;
    const auto where = [&] { return "line " + std::to_string(lines.line_number()); };
    double xyz[3];
    if (parse_fields(line, xyz, what))
      builder.add(xyz[0], xyz[1], xyz[2], where);
    else
      builder.reject(where(), what);
    builder.progress(lines.offset());
  }
  return builder.finish();
}

}  // namespace polarform
