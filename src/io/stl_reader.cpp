#include "src/io/stl_reader.h"

#include <cstdint>
#include <string>

#include "src/io/binary_load.h"
#include "src/io/cloud_builder.h"
#include "src/io/text_scan.h"

namespace polarform {

using namespace io_detail;

namespace {

constexpr std::size_t kHeaderBytes = 84;    // 80-byte comment + uint32 triangle count
constexpr std::size_t kTriangleBytes = 50;  // normal, 3 vertices (12 floats), uint16 attribute

std::uint64_t declared_triangles(std::string_view bytes) {
  return load<std::uint32_t>(bytes.data() + 80, ByteOrder::little);
}

// ASCII STL starts with "solid" and is text: a NUL byte early on means a binary file whose
// header happens to start with "solid" (its size check failed, so it is damaged).
bool looks_like_ascii(std::string_view bytes) {
  const char* p = skip_blanks(bytes.data(), bytes.data() + bytes.size());
  const std::string_view text(p, bytes.data() + bytes.size() - p);
  return text.starts_with("solid") && text.substr(0, 512).find('\0') == std::string_view::npos;
}

void read_binary(std::string_view bytes, CloudBuilder& builder) {
  const std::uint64_t triangles = declared_triangles(bytes);
  builder.reserve(3 * triangles);
  for (std::uint64_t t = 0; t < triangles; ++t) {
    const std::size_t triangle = kHeaderBytes + t * kTriangleBytes;
    for (int v = 0; v < 3; ++v) {
      const char* p = bytes.data() + triangle + 12 + 12 * v;
      builder.add(load<float>(p, ByteOrder::little), load<float>(p + 4, ByteOrder::little),
                  load<float>(p + 8, ByteOrder::little), [&] {
                    return "triangle " + std::to_string(t) + " vertex " + std::to_string(v) +
                           " (byte offset " + std::to_string(p - bytes.data()) + ")";
                  });
    }
    builder.progress(triangle + kTriangleBytes);
  }
}

void read_ascii(std::string_view bytes, CloudBuilder& builder) {
  builder.reserve(count_keyword_lines(bytes, "vertex"));
  LineCursor lines(bytes);
  std::string what;
  for (std::string_view line; lines.next(line);) {
    std::string_view rest = line;
    const std::string_view keyword = next_token(rest);
    const auto where = [&] { return "line " + std::to_string(lines.line_number()); };
    if (keyword == "vertex") {
      double xyz[3];
      if (parse_coordinates(rest, xyz, 3, what))
        builder.add(xyz[0], xyz[1], xyz[2], where);
      else
        builder.reject(where(), what);
    } else if (!keyword.empty() && keyword != "solid" && keyword != "endsolid" &&
               keyword != "facet" && keyword != "endfacet" && keyword != "outer" &&
               keyword != "endloop") {
      builder.fail(where(), "unknown ASCII STL keyword " + quoted(keyword) +
                                ": expected solid, facet, outer loop, vertex, endloop, endfacet "
                                "or endsolid");
    }
    builder.progress(lines.offset());
  }
}

// A binary STL whose size does not match its triangle count: say which way it is off.
[[noreturn]] void fail_binary_size(std::string_view bytes, const CloudBuilder& builder) {
  const std::uint64_t triangles = declared_triangles(bytes);
  const std::uint64_t expected = kHeaderBytes + kTriangleBytes * triangles;
  const std::string declared = "binary STL header declares " + std::to_string(triangles) +
                               " triangles (" + std::to_string(expected) +
                               " bytes), the file has " + std::to_string(bytes.size());
  if (bytes.size() > expected)
    builder.fail("", declared + ": wrong triangle count, or not an STL file");
  const std::uint64_t complete = (bytes.size() - kHeaderBytes) / kTriangleBytes;
  const std::string at = "triangle " + std::to_string(complete) + " (byte offset " +
                         std::to_string(kHeaderBytes + complete * kTriangleBytes) + ")";
  if ((bytes.size() - kHeaderBytes) % kTriangleBytes == 0)
    builder.fail(at, "the file ends before this triangle: " + declared);
  builder.fail(at, "the file is truncated inside this triangle: " + declared);
}

}  // namespace

bool has_binary_stl_size(std::string_view bytes) {
  return bytes.size() >= kHeaderBytes &&
         bytes.size() == kHeaderBytes + kTriangleBytes * declared_triangles(bytes);
}

PointCloud parse_stl(std::string_view bytes, std::string_view name, const ReadOptions& options) {
  CloudBuilder builder(name, bytes.size(), options);
  if (has_binary_stl_size(bytes)) {
    read_binary(bytes, builder);
  } else if (looks_like_ascii(bytes)) {
    read_ascii(bytes, builder);
  } else if (bytes.size() < kHeaderBytes) {
    builder.fail("",
                 "not an STL file: shorter than the 84-byte binary header and not starting "
                 "with 'solid'");
  } else {
    fail_binary_size(bytes, builder);
  }
  return builder.finish();
}

}  // namespace polarform
