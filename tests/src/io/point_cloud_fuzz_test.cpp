// Bounded mutation fuzzing (tests/support/bounded_mutator.h) of the point-cloud readers: xyz/csv,
// PLY ascii and binary in both byte orders, STL ascii and binary, OBJ, OFF, each through
// parse_point_cloud. Every mutant parses into at least three finite points or throws InputError.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "src/io/point_cloud.h"
#include "tests/support/src/bounded_mutator.h"

namespace polarform {
namespace {

using fuzz_test::fuzz;
using fuzz_test::iterations;

std::string ascii_points(const char* separator) {
  std::string out;
  for (int k = 0; k < 12; ++k)
    out += std::to_string(std::cos(k * 0.5)) + separator + std::to_string(std::sin(k * 0.5)) +
           separator + std::to_string(0.1 * k) + "\n";
  return out;
}

template <class T>
void append(std::string& out, T value, bool big_endian) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (big_endian) std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

std::string binary_ply(bool big_endian) {
  std::string out = std::string("ply\nformat ") +
                    (big_endian ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
                    "property double z\nproperty uchar red\nelement face 1\n"
                    "property list uchar int vertex_indices\nend_header\n";
  for (int k = 0; k < 6; ++k) {
    append<float>(out, static_cast<float>(std::cos(k)), big_endian);
    append<float>(out, static_cast<float>(std::sin(k)), big_endian);
    append<double>(out, 0.25 * k, big_endian);
    append<std::uint8_t>(out, static_cast<std::uint8_t>(k), big_endian);
  }
  append<std::uint8_t>(out, 3, big_endian);
  for (int v : {0, 1, 2}) append<std::int32_t>(out, v, big_endian);
  return out;
}

std::string binary_stl() {
  std::string out(80, ' ');
  append<std::uint32_t>(out, 2, false);
  for (int t = 0; t < 2; ++t) {
    for (int k = 0; k < 12; ++k) append<float>(out, static_cast<float>(k + t), false);
    append<std::uint16_t>(out, 0, false);
  }
  return out;
}

const std::string kAsciiPly =
    "ply\nformat ascii 1.0\ncomment fuzz seed\nelement vertex 4\nproperty double x\n"
    "property double y\nproperty double z\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
const std::string kAsciiStl =
    "solid s\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
    "   vertex 0 1 0\n  endloop\n endfacet\nendsolid s\n";
const std::string kObj = "# seed\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1 1\nvn 0 0 1\nf 1 2 3\n";
const std::string kOff = "OFF\n# seed\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n";

void parse_cloud(const std::string& bytes, const char* name) {
  const PointCloud cloud = parse_point_cloud(bytes, name);
  ASSERT_GE(cloud.points.cols(), 3);
  ASSERT_TRUE(cloud.points.allFinite());
}

struct CloudSeed {
  const char* name;
  std::string bytes;
};

TEST(ParserFuzz, PointCloudReadersAcceptOrRejectCleanly) {
  const std::vector<CloudSeed> seeds = {
      {"scan.xyz", ascii_points(" ")},       {"scan.csv", "x,y,z\n" + ascii_points(",")},
      {"scan.ply", kAsciiPly},               {"le.ply", binary_ply(false)},
      {"be.ply", binary_ply(true)},          {"mesh.stl", kAsciiStl},
      {"binary.stl", binary_stl()},          {"mesh.obj", kObj},
      {"mesh.off", kOff}};
  std::uint64_t rng_seed = 1;
  for (const CloudSeed& s : seeds) {
    SCOPED_TRACE(s.name);
    fuzz(s.bytes, [&](const std::string& bytes) { parse_cloud(bytes, s.name); }, rng_seed++,
         iterations());
  }
}

}  // namespace
}  // namespace polarform
