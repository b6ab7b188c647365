// PLY output of a point set, optionally with a colour and one named scalar per point -- e.g.
// deviation.ply: the scan coloured by signed distance, with the distance itself as a property.
// Binary little-endian by default, ascii on request; coordinates are written as double so they
// read back (src/io/point_cloud.h) bit for bit. Written atomically.
#pragma once

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <functional>
#include <ostream>
#include <string_view>
#include <vector>

namespace polarform {

// Throws InputError if a coordinate is NaN or infinite, colors or scalar do not hold one entry
// per point, scalar_name is not a plain identifier (letters, digits, '_') or clashes with x, y,
// z, red, green, blue, or the file cannot be written.
void write_ply(const std::filesystem::path& path, const Eigen::Matrix3Xd& points,
               const std::vector<std::array<unsigned char, 3>>* colors = nullptr,
               const std::vector<double>* scalar = nullptr, std::string_view scalar_name = "value",
               bool binary = true);

// The same checks (path names the file in messages), and a writer of the file's bytes to a
// stream, for an output transaction; points, colors and scalar must outlive it.
std::function<void(std::ostream&)> ply_writer(
    const std::filesystem::path& path, const Eigen::Matrix3Xd& points,
    const std::vector<std::array<unsigned char, 3>>* colors = nullptr,
    const std::vector<double>* scalar = nullptr, std::string_view scalar_name = "value",
    bool binary = true);

}  // namespace polarform
