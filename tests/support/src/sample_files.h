// Small valid files of every supported point-cloud format, built in memory from known points, for
// the reader tests, their fuzz test and the PLY writer's test. The builders are independent of the
// readers: binary values are laid out byte by byte here, text is written with std::to_chars.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "src/error.h"

namespace polarform::io_test {

// Six points whose coordinates are exact in float, so every format reproduces them exactly.
inline Eigen::Matrix3Xd sample_points() {
  Eigen::Matrix3Xd p(3, 6);
  p << 1.5, -2.25, 0.0, 100.125, -0.5, 3.0,  //
      2.0, 0.75, -7.5, 4.0, 1024.0, -0.125,  //
      -3.5, 6.0, 0.25, -12.0, 8.5, 9.75;
  return p;
}

inline std::string number(double value) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof(text), value).ptr);
}

// Appends value as sizeof(T) bytes in little- (big = false) or big-endian order.
template <class T>
void put(std::string& out, T value, bool big) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  const bool little_host = [] {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
  }();
  for (std::size_t i = 0; i < sizeof(T); ++i) {
    const std::size_t k = (little_host != big) ? i : sizeof(T) - 1 - i;
    out += static_cast<char>(bytes[k]);
  }
}

enum class PlyKind { ascii, binary_little_endian, binary_big_endian };

// A PLY file of the points with everything a reader must skip: an element "material" before the
// vertices, vertex properties of other types around x, y, z (optionally a list among them), and
// elements "face" (a list) and "edge" after them. Coordinates are float or double.
inline std::string sample_ply(const Eigen::Matrix3Xd& points, PlyKind kind, bool doubles,
                              bool vertex_list = true) {
  const char* real = doubles ? "double" : "float";
  const auto n = static_cast<int>(points.cols());
  std::string out = "ply\nformat ";
  out += kind == PlyKind::ascii                  ? "ascii"
         : kind == PlyKind::binary_little_endian ? "binary_little_endian"
                                                 : "binary_big_endian";
  out += " 1.0\ncomment made by the polarform tests\nobj_info nothing\n";
  out += "element material 2\nproperty list uchar int ids\nproperty float shine\n";
  out += "element vertex " + std::to_string(n) + "\nproperty uchar flags\n";
  out += std::string("property ") + real + " x\nproperty short id\nproperty " + real + " y\n";
  if (vertex_list) out += "property list uchar int neighbours\n";
  out += std::string("property ") + real + " z\nproperty float intensity\n";
  out += "element face 2\nproperty list uchar int vertex_indices\n";
  out += "element edge 1\nproperty int v1\nproperty int v2\nend_header\n";
  if (kind == PlyKind::ascii) {
    out += "2 7 8 0.5\n0 1.25\n";
    for (int i = 0; i < n; ++i) {
      out += "255 " + number(points(0, i)) + " -" + std::to_string(i) + " " + number(points(1, i));
      if (vertex_list) {
        out += " " + std::to_string(i % 3);
        for (int j = 0; j < i % 3; ++j) out += " " + std::to_string(j);
      }
      out += " " + number(points(2, i)) + " 0.5\n";
    }
    return out + "3 0 1 2\n4 0 1 2 3\n0 1\n";
  }
  const bool big = kind == PlyKind::binary_big_endian;
  const auto put_real = [&](double v) {
    if (doubles)
      put<double>(out, v, big);
    else
      put<float>(out, static_cast<float>(v), big);
  };
  put<std::uint8_t>(out, 2, big);
  put<std::int32_t>(out, 7, big);
  put<std::int32_t>(out, 8, big);
  put<float>(out, 0.5f, big);
  put<std::uint8_t>(out, 0, big);
  put<float>(out, 1.25f, big);
  for (int i = 0; i < n; ++i) {
    put<std::uint8_t>(out, 255, big);
    put_real(points(0, i));
    put<std::int16_t>(out, static_cast<std::int16_t>(-i), big);
    put_real(points(1, i));
    if (vertex_list) {
      put<std::uint8_t>(out, static_cast<std::uint8_t>(i % 3), big);
      for (int j = 0; j < i % 3; ++j) put<std::int32_t>(out, j, big);
    }
    put_real(points(2, i));
    put<float>(out, 0.5f, big);
  }
  for (int f = 3; f <= 4; ++f) {
    put<std::uint8_t>(out, static_cast<std::uint8_t>(f), big);
    for (int j = 0; j < f; ++j) put<std::int32_t>(out, j, big);
  }
  put<std::int32_t>(out, 0, big);
  put<std::int32_t>(out, 1, big);
  return out;
}

// Binary STL of the points taken three at a time as triangles; the 80-byte header starts with
// `header` (e.g. "solid part", which must not fool the reader).
inline std::string binary_stl(const Eigen::Matrix3Xd& points, std::string_view header) {
  std::string out(header.substr(0, 80));
  out.resize(80, ' ');
  const auto triangles = static_cast<std::uint32_t>(points.cols() / 3);
  put<std::uint32_t>(out, triangles, false);
  for (std::uint32_t t = 0; t < triangles; ++t) {
    for (int k = 0; k < 3; ++k) put<float>(out, k == 2 ? 1.0f : 0.0f, false);
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) put<float>(out, static_cast<float>(points(k, 3 * t + v)), false);
    put<std::uint16_t>(out, 0, false);
  }
  return out;
}

inline std::string ascii_stl(const Eigen::Matrix3Xd& points) {
  std::string out = "solid part\n";
  for (int t = 0; t < points.cols() / 3; ++t) {
    out += "  facet normal 0 0 1\n    outer loop\n";
    for (int v = 0; v < 3; ++v) {
      out += "      vertex";
      for (int k = 0; k < 3; ++k) out += " " + number(points(k, 3 * t + v));
      out += "\n";
    }
    out += "    endloop\n  endfacet\n";
  }
  return out + "endsolid part\n";
}

// OBJ with comments, normals, texture coordinates, groups and faces around the v lines.
inline std::string sample_obj(const Eigen::Matrix3Xd& points) {
  std::string out = "# exported\nmtllib part.mtl\no part\n";
  for (int i = 0; i < points.cols(); ++i) {
    out += "v " + number(points(0, i)) + " " + number(points(1, i)) + " " + number(points(2, i));
    out += i % 2 ? " 1.0\n" : " 0.5 0.5 0.5\n";
    out += "vn 0 0 1\nvt 0.5 0.5\n";
  }
  return out + "g side\nusemtl steel\nf 1/1/1 2/2/2 3/3/3\nf 4 5 6\n";
}

// OFF with the given keyword ("OFF", "COFF", "NOFF", ...), comments and faces; extra columns
// (normals, colours) after x y z.
inline std::string sample_off(const Eigen::Matrix3Xd& points, std::string_view keyword = "OFF") {
  std::string out = std::string(keyword) + "\n# a comment\n\n";
  out += std::to_string(points.cols()) + " 2 0\n";
  for (int i = 0; i < points.cols(); ++i)
    out += number(points(0, i)) + " " + number(points(1, i)) + " " + number(points(2, i)) +
           (keyword == "OFF" ? "\n" : " 0 0 1 0.5\n");
  return out + "3 0 1 2\n3 3 4 5 255 0 0\n";
}

// Delimited text: a header line, a comment, CRLF line ends and a fourth column.
inline std::string sample_xyz(const Eigen::Matrix3Xd& points, bool commas) {
  const std::string sep = commas ? ", " : " \t";
  std::string out = commas ? "x,y,z,intensity\r\n" : "X Y Z intensity\r\n";
  out += "# scanner: test\r\n";
  for (int i = 0; i < points.cols(); ++i)
    out += number(points(0, i)) + sep + number(points(1, i)) + sep + number(points(2, i)) + sep +
           "17\r\n";
  return out;
}

// The message of the InputError that f() throws; fails the test if it throws nothing or
// something else.
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
    return {};
  }
  ADD_FAILURE() << "expected InputError, nothing was thrown";
  return {};
}

}  // namespace polarform::io_test
