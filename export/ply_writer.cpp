#include "export/ply_writer.h"

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <utility>

#include "export/atomic_file.h"
#include "src/error.h"

namespace polarform {

namespace {

void validate(const std::filesystem::path& path, const Eigen::Matrix3Xd& points,
              const std::vector<std::array<unsigned char, 3>>* colors,
              const std::vector<double>* scalar, std::string_view scalar_name) {
  const std::string file = path.string() + ": ";
  const auto n = static_cast<std::size_t>(points.cols());
  for (std::size_t i = 0; i < n; ++i)
    if (!points.col(static_cast<Eigen::Index>(i)).allFinite())
      throw InputError(file + "point " + std::to_string(i) + " has a NaN or infinite coordinate");
  if (colors && colors->size() != n)
    throw InputError(file + std::to_string(colors->size()) + " colours for " + std::to_string(n) +
                     " points: expected one per point");
  if (!scalar) return;
  if (scalar->size() != n)
    throw InputError(file + std::to_string(scalar->size()) + " values of '" +
                     std::string(scalar_name) + "' for " + std::to_string(n) +
                     " points: expected one per point");
  const bool identifier = !scalar_name.empty() &&
                          scalar_name.find_first_not_of(
                              "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") ==
                              std::string_view::npos;
  const bool taken = scalar_name == "x" || scalar_name == "y" || scalar_name == "z" ||
                     scalar_name == "red" || scalar_name == "green" || scalar_name == "blue";
  if (!identifier || taken)
    throw InputError(file + "scalar property name '" + std::string(scalar_name) +
                     "': expected letters, digits or '_', other than x y z red green blue");
}

std::string header(std::size_t count, bool has_colors, const std::vector<double>* scalar,
                   std::string_view scalar_name, bool binary) {
  std::string h = "ply\nformat ";
  h += binary ? "binary_little_endian" : "ascii";
  h += " 1.0\ncomment polarform point set\nelement vertex " + std::to_string(count) +
       "\nproperty double x\nproperty double y\nproperty double z\n";
  if (has_colors) h += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  if (scalar) h.append("property double ").append(scalar_name).append("\n");
  return h + "end_header\n";
}

// One vertex record: the coordinates, and the colour and scalar when the file has them.
struct Record {
  Eigen::Vector3d xyz;
  const std::array<unsigned char, 3>* color;
  const double* value;
};

void append_little_endian(std::string& out, double value) {
  char bytes[sizeof(double)];
  std::memcpy(bytes, &value, sizeof(double));
  if constexpr (std::endian::native == std::endian::big)
    for (std::size_t i = 0; i < sizeof(double) / 2; ++i)
      std::swap(bytes[i], bytes[sizeof(double) - 1 - i]);
  out.append(bytes, sizeof(double));
}

void append_binary(std::string& out, const Record& r) {
  for (int k = 0; k < 3; ++k) append_little_endian(out, r.xyz(k));
  if (r.color)
    for (const unsigned char c : *r.color) out += static_cast<char>(c);
  if (r.value) append_little_endian(out, *r.value);
}

// Shortest text that reads back to the same double.
void append_text(std::string& out, double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof(text), value);
  out.append(text, result.ptr);
}

void append_ascii(std::string& out, const Record& r) {
  for (int k = 0; k < 3; ++k) {
    if (k > 0) out += ' ';
    append_text(out, r.xyz(k));
  }
  if (r.color)
    for (const unsigned char c : *r.color) out.append(" ").append(std::to_string(c));
  if (r.value) {
    out += ' ';
    append_text(out, *r.value);
  }
  out += '\n';
}

}  // namespace

void write_ply(const std::filesystem::path& path, const Eigen::Matrix3Xd& points,
               const std::vector<std::array<unsigned char, 3>>* colors,
               const std::vector<double>* scalar, std::string_view scalar_name, bool binary) {
  write_file_atomically(path, ply_writer(path, points, colors, scalar, scalar_name, binary));
}

std::function<void(std::ostream&)> ply_writer(
    const std::filesystem::path& path, const Eigen::Matrix3Xd& points,
    const std::vector<std::array<unsigned char, 3>>* colors, const std::vector<double>* scalar,
    std::string_view scalar_name, bool binary) {
  validate(path, points, colors, scalar, scalar_name);
  return [&points, colors, scalar, name = std::string(scalar_name), binary](std::ostream& out) {
    const auto n = static_cast<std::size_t>(points.cols());
    out << header(n, colors != nullptr, scalar, name, binary);
    std::string chunk;
    constexpr std::size_t kChunkBytes = 1 << 16;
    chunk.reserve(kChunkBytes + 256);
    for (std::size_t i = 0; i < n; ++i) {
      const Record record{points.col(static_cast<Eigen::Index>(i)),
                          colors ? &(*colors)[i] : nullptr, scalar ? &(*scalar)[i] : nullptr};
      if (binary)
        append_binary(chunk, record);
      else
        append_ascii(chunk, record);
      if (chunk.size() >= kChunkBytes) {
        out.write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        chunk.clear();
      }
    }
    out.write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
  };
}

}  // namespace polarform
