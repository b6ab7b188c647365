// Point-cloud input: one entry point that reads a scan or mesh file (xyz/csv/txt, PLY, STL, OBJ,
// OFF) into a 3 x n matrix. The format comes from strong content signatures first (PLY magic, OFF
// keyword, binary STL size), then the extension, then weaker sniffing; the per-format parsers are
// declared in src/io/<format>_reader.h. Bad input throws InputError naming file and line/vertex.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string_view>

namespace polarform {

struct PointCloud {
  Eigen::Matrix3Xd points;  // one point per column, finite coordinates
  std::size_t dropped = 0;  // bad records skipped (only with ReadOptions::skip_bad)
};

struct ReadOptions {
  // Drop records with unparsable, NaN or infinite coordinates (counted in PointCloud::dropped)
  // instead of throwing. Structural errors (bad header, truncation) always throw.
  bool skip_bad = false;
  // Called with the fraction of the file read, in (0, 1], increasing, at most 100 times.
  std::function<void(double)> progress;
};

enum class CloudFormat { xyz, ply, stl, obj, off };

// Reads the file (memory-mapped, parsed in place). Throws InputError if it cannot be read, is
// malformed, or holds fewer than 3 points.
PointCloud read_point_cloud(const std::filesystem::path& file, const ReadOptions& options = {});

// The same for a file already in memory; `name` is used for the extension and in messages.
PointCloud parse_point_cloud(std::string_view bytes, std::string_view name,
                             const ReadOptions& options = {});

// The format read_point_cloud would use for these bytes under this file name.
CloudFormat detect_cloud_format(std::string_view name, std::string_view bytes);

}  // namespace polarform
