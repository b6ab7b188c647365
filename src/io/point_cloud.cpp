#include "src/io/point_cloud.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>

#include "src/error.h"
#include "src/io/mapped_file.h"
#include "src/io/obj_reader.h"
#include "src/io/off_reader.h"
#include "src/io/ply_reader.h"
#include "src/io/stl_reader.h"
#include "src/io/text_scan.h"
#include "src/io/xyz_reader.h"

namespace polarform {

using namespace io_detail;

namespace {

// The first line with content (no comment, not blank) within the first 64 KiB.
std::string_view first_content_line(std::string_view bytes) {
  if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);
  LineCursor lines(bytes.substr(0, 65536));
  for (std::string_view line; lines.next(line);)
    if (const std::string_view content = strip_comment(line); !content.empty()) return content;
  return {};
}

std::optional<CloudFormat> format_from_extension(std::string_view name) {
  std::string ext = std::filesystem::path(name).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".ply") return CloudFormat::ply;
  if (ext == ".stl") return CloudFormat::stl;
  if (ext == ".obj") return CloudFormat::obj;
  if (ext == ".off") return CloudFormat::off;
  if (ext == ".xyz" || ext == ".csv" || ext == ".txt" || ext == ".asc" || ext == ".pts")
    return CloudFormat::xyz;
  return std::nullopt;
}

bool has_ply_magic(std::string_view bytes) {
  const std::string_view head = bytes.substr(0, 16);
  return trim(head.substr(0, head.find('\n'))) == "ply";
}

bool is_obj_statement(std::string_view line) {
  const std::string_view keyword = next_token(line);
  return keyword == "v" || keyword == "vn" || keyword == "vt" || keyword == "f" || keyword == "o" ||
         keyword == "g" || keyword == "mtllib" || keyword == "usemtl";
}

}  // namespace

CloudFormat detect_cloud_format(std::string_view name, std::string_view bytes) {
  // Signatures that no other format can carry override the extension.
  if (has_ply_magic(bytes)) return CloudFormat::ply;
  const std::string_view first = first_content_line(bytes);
  if (match_off_keyword(first)) return CloudFormat::off;
  if (has_binary_stl_size(bytes)) return CloudFormat::stl;
  if (const auto format = format_from_extension(name)) return *format;
  if (first.starts_with("solid")) return CloudFormat::stl;
  if (is_obj_statement(first)) return CloudFormat::obj;
  return CloudFormat::xyz;
}

PointCloud parse_point_cloud(std::string_view bytes, std::string_view name,
                             const ReadOptions& options) {
  if (bytes.empty()) throw InputError(std::string(name) + ": file is empty");
  switch (detect_cloud_format(name, bytes)) {
    case CloudFormat::ply:
      return parse_ply(bytes, name, options);
    case CloudFormat::stl:
      return parse_stl(bytes, name, options);
    case CloudFormat::obj:
      return parse_obj(bytes, name, options);
    case CloudFormat::off:
      return parse_off(bytes, name, options);
    case CloudFormat::xyz:
      break;
  }
  return parse_xyz(bytes, name, options);
}

PointCloud read_point_cloud(const std::filesystem::path& file, const ReadOptions& options) {
  const MappedFile mapped(file);
  return parse_point_cloud(mapped.bytes(), file.string(), options);
}

}  // namespace polarform
