#include "src/io/off_reader.h"

#include <cstdint>
#include <string>

#include "src/io/cloud_builder.h"
#include "src/io/text_scan.h"

namespace polarform {

using namespace io_detail;

namespace {

// The lines of an OFF file with comments and blank lines removed.
class ContentLines {
 public:
  explicit ContentLines(std::string_view bytes) : lines_(bytes) {}

  bool next(std::string_view& content) {
    for (std::string_view line; lines_.next(line);) {
      content = strip_comment(line);
      if (!content.empty()) return true;
    }
    return false;
  }

  std::string here() const { return "line " + std::to_string(lines_.line_number()); }
  std::size_t offset() const { return lines_.offset(); }

 private:
  LineCursor lines_;
};

// Parses one vertex line of `components` values into x y z (divided by the last component if
// homogeneous); on failure `what` says what was expected.
bool parse_vertex(std::string_view rest, std::uint64_t components, bool homogeneous, double xyz[3],
                  std::string& what) {
  if (!parse_coordinates(rest, xyz, 3, what)) return false;
  double last = xyz[2];
  for (std::uint64_t k = 3; k < components; ++k) {
    const std::string_view token = next_token(rest);
    if (token.empty() || !parse_double(token, last)) {
      what = token.empty() ? "expected " + std::to_string(components) + " components, found " +
                                 std::to_string(k)
                           : "invalid number " + quoted(token) + ": expected a decimal number";
      return false;
    }
  }
  if (!homogeneous) return true;
  if (last == 0.0) {
    what = "homogeneous coordinate is 0: the vertex is at infinity";
    return false;
  }
  for (int c = 0; c < 3; ++c) xyz[c] /= last;
  return true;
}

}  // namespace

std::optional<OffKeyword> match_off_keyword(std::string_view text) {
  std::size_t n = 0;
  const auto prefix = [&](std::string_view p) {
    const bool present = text.substr(n).starts_with(p);
    if (present) n += p.size();
    return present;
  };
  prefix("ST");
  prefix("C");
  prefix("N");
  const bool homogeneous = prefix("4");
  const bool dimension_line = prefix("n");
  if (!prefix("OFF")) return std::nullopt;
  const bool ends_token =
      n == text.size() || is_blank(text[n]) || text[n] == '#' || (text[n] >= '0' && text[n] <= '9');
  if (!ends_token) return std::nullopt;
  return OffKeyword{n, homogeneous, dimension_line};
}

PointCloud parse_off(std::string_view bytes, std::string_view name, const ReadOptions& options) {
  CloudBuilder builder(name, bytes.size(), options);
  ContentLines lines(bytes);
  std::string_view rest;
  if (!lines.next(rest)) builder.fail("", "empty OFF file: expected 'OFF' and the counts");
  bool homogeneous = false;
  std::uint64_t dimension = 3;
  if (const auto keyword = match_off_keyword(rest)) {
    rest = trim(rest.substr(keyword->length));
    if (rest.starts_with("BINARY"))
      builder.fail(lines.here(), "binary OFF is not supported: convert it to ascii OFF or to PLY");
    homogeneous = keyword->homogeneous;
    if (keyword->dimension_line) {
      if (rest.empty() && !lines.next(rest))
        builder.fail(lines.here(), "file ends before the vertex dimension of nOFF");
      if (!parse_count(next_token(rest), dimension) || dimension < 3)
        builder.fail(lines.here(),
                     "expected the vertex dimension of nOFF, an integer of at least 3");
      rest = trim(rest);
    }
    if (rest.empty() && !lines.next(rest))
      builder.fail(lines.here(), "file ends before the counts");
  }
  std::uint64_t vertices, faces;
  if (!parse_count(next_token(rest), vertices) || !parse_count(next_token(rest), faces))
    builder.fail(lines.here(),
                 "expected the counts 'NVertices NFaces NEdges' as non-negative integers");
  builder.reserve(vertices);
  const std::uint64_t components = dimension + (homogeneous ? 1 : 0);
  std::string what;
  for (std::uint64_t i = 0; i < vertices; ++i) {
    if (!lines.next(rest))
      builder.fail(lines.here(),
                   "file ends after " + std::to_string(i) + " of the " + std::to_string(vertices) +
                       " vertices: the file is truncated or the vertex count is wrong");
    const auto where = [&] { return lines.here() + " (vertex " + std::to_string(i) + ")"; };
    double xyz[3];
    if (parse_vertex(rest, components, homogeneous, xyz, what))
      builder.add(xyz[0], xyz[1], xyz[2], where);
    else
      builder.reject(where(), what);
    builder.progress(lines.offset());
  }
  return builder.finish();
}

}  // namespace polarform
