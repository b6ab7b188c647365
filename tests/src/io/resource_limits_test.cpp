// Hostile point-cloud files read through the sniffing entry point: a header that claims 10^12
// vertices or triangles, coordinates that overflow or are NaN, a line of 64 MB. Each is an
// InputError naming the file and what is wrong — never an allocation of the claimed size (that
// would escape as std::bad_alloc, or exhaust memory), never a hang.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "src/error.h"
#include "src/io/point_cloud.h"

namespace polarform {
namespace {

std::string error_of(const std::string& bytes, const std::string& name) {
  try {
    parse_point_cloud(bytes, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string ply_header(const std::string& format, const std::string& count) {
  return "ply\nformat " + format + " 1.0\nelement vertex " + count +
         "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
}

TEST(ResourceLimits, HeadersClaimingATrillionElementsAreErrors) {
  const std::string trillion = "1000000000000";
  float xyz[3] = {1, 2, 3};
  const std::string one_binary_vertex(reinterpret_cast<const char*>(xyz), sizeof xyz);
  std::string stl(80, 'x');
  const std::uint32_t triangles = 4000000000u;  // 200 GB of triangles claimed
  stl.append(reinterpret_cast<const char*>(&triangles), 4);
  stl.append(50, '\0');
  const std::pair<std::string, std::string> cases[] = {
      {"a.ply", ply_header("ascii", trillion) + "1 2 3\n"},
      {"b.ply", ply_header("binary_little_endian", trillion) + one_binary_vertex},
      {"c.off", "OFF\n" + trillion + " 0 0\n1 2 3\n"},
      {"d.stl", stl}};
  for (const auto& [name, bytes] : cases) {
    const std::string e = error_of(bytes, name);
    EXPECT_EQ(e.rfind(name + ": ", 0), 0u) << e;
    EXPECT_TRUE(e.find(trillion) != std::string::npos || e.find("4000000000") != std::string::npos)
        << e;
  }
}

TEST(ResourceLimits, OverflowingAndNotANumberCoordinatesAreErrors) {
  const std::string good = "1 2 3\n4 5 6\n7 8 10\n";
  EXPECT_EQ(error_of(good + "1e400 1 2\n", "a.xyz"),
            "a.xyz: line 4: invalid number '1e400': expected x as a decimal number");
  EXPECT_EQ(error_of(good + "1 nan 2\n", "a.xyz"),
            "a.xyz: line 4: y is NaN or infinite: expected a finite coordinate");
}

TEST(ResourceLimits, AHugeLineIsOneErrorWithAShortMessage) {
  const std::string line(64u << 20, '1');
  const std::string e = error_of(line + "\n", "long.xyz");
  EXPECT_EQ(e.rfind("long.xyz: line 1: invalid number '111", 0), 0u) << e.substr(0, 200);
  EXPECT_LT(e.size(), 200u);  // the token is elided, not echoed
}

}  // namespace
}  // namespace polarform
