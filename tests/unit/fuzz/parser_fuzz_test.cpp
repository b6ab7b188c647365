// Bounded mutation fuzzing of every parser polarform owns: point clouds (xyz/csv, PLY ascii and
// binary in both byte orders, STL ascii and binary, OBJ, OFF), the cam, vessel and fit project
// files, and the studio's --script (when the studio is built). Each valid seed is mutated (byte
// flips, deletions, duplications, insertions of number-breaking tokens, truncation) with a fixed
// seed; every mutant must either parse into a valid result or throw InputError — no other
// exception, no crash (run `make asan` for memory errors). POLARFORM_FUZZ_ITERATIONS scales the
// run (default 10000 mutants per seed).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

#include "jobs/project/cam_project.h"
#include "jobs/project/fit_project.h"
#include "jobs/project/vessel_project.h"
#include "src/error.h"
#include "src/io/point_cloud.h"
#ifdef POLARFORM_HAVE_STUDIO_LOGIC
#include "ui/studio/studio_script.h"
#endif

namespace polarform {
namespace {

int iterations() {
  const char* env = std::getenv("POLARFORM_FUZZ_ITERATIONS");
  return env ? std::max(1, std::atoi(env)) : 10000;
}

std::string read_text(const std::string& relative) {
  std::ifstream in(std::string(POLARFORM_SOURCE_DIR) + "/" + relative, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

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

// One mutation of `s`, drawn from `rng`.
std::string mutate(std::string s, std::mt19937_64& rng) {
  static const char* const kTokens[] = {"nan", "inf", "-", "1e999", "0x", ",", "\n", " ", "\0",
                                        "element vertex 99999999999\n", "<", "\"", "=", "/>",
                                        "property list uchar int x\n", "end_header\n", "-1"};
  const auto pick = [&](std::size_t n) {
    return n == 0 ? std::size_t{0} : static_cast<std::size_t>(rng() % n);
  };
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits; ++e) {
    const std::size_t at = pick(s.size() + 1);
    switch (rng() % 6) {
      case 0:
        if (!s.empty()) s[pick(s.size())] ^= static_cast<char>(1u << (rng() % 8));
        break;
      case 1:
        s.erase(std::min(at, s.size()), pick(16) + 1);
        break;
      case 2: {
        const std::size_t from = pick(s.size());
        s.insert(at, s.substr(from, pick(24) + 1));
        break;
      }
      case 3: {
        const char* token = kTokens[pick(std::size(kTokens))];
        s.insert(at, token, std::max<std::size_t>(1, std::strlen(token)));
        break;
      }
      case 4:
        s.resize(std::min(at, s.size()));
        break;
      default:
        if (!s.empty()) s[pick(s.size())] = static_cast<char>(rng() % 256);
        break;
    }
  }
  return s;
}

// Feeds `count` mutants of `seed` to `parse`; counts accepted and rejected ones.
void fuzz(const std::string& seed, const std::function<void(const std::string&)>& parse,
          std::uint64_t rng_seed, int count) {
  ASSERT_NO_THROW(parse(seed)) << "the seed itself must parse";
  std::mt19937_64 rng(rng_seed);
  int rejected = 0;
  for (int k = 0; k < count; ++k) {
    const std::string input = mutate(seed, rng);
    try {
      parse(input);
    } catch (const InputError&) {
      ++rejected;
    } catch (const std::exception& e) {
      FAIL() << "mutant " << k << " threw " << typeid(e).name() << ": " << e.what();
    }
  }
  // A fuzzer whose mutants all pass tests nothing; one whose mutants all fail may never reach
  // past the first check — both would make this test meaningless.
  EXPECT_GT(rejected, count / 20);
}

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

TEST(ParserFuzz, CamProjectReaderAcceptsOrRejectsCleanly) {
  std::uint64_t rng_seed = 100;
  for (const char* example : {"examples/cams/roller.xml", "examples/cams/polynomial.xml",
                              "examples/cams/cylindrical.xml"}) {
    SCOPED_TRACE(example);
    fuzz(read_text(example),
         [](const std::string& text) {
           std::vector<std::string> warnings;
           parse_cam_project(text, "fuzz.xml", warnings);
         },
         rng_seed++, iterations());
  }
}

TEST(ParserFuzz, VesselProjectReaderAcceptsOrRejectsCleanly) {
  std::uint64_t rng_seed = 200;
  for (const char* example :
       {"examples/vessels/torispherical_100_6.xml", "examples/vessels/custom_curvature.xml"}) {
    SCOPED_TRACE(example);
    fuzz(read_text(example),
         [](const std::string& text) {
           std::vector<std::string> warnings;
           parse_vessel_project(text, "fuzz.xml", warnings);
         },
         rng_seed++, iterations());
  }
}

TEST(ParserFuzz, FitProjectReaderAcceptsOrRejectsCleanly) {
  const auto parse = [](const std::string& text) {
    std::vector<std::string> warnings;
    parse_fit_project(text, "fuzz.xml", warnings);
  };
  fuzz(read_text("examples/scans/sphere_like_fit.xml"), parse, 300, iterations());
  // Every attribute at once.
  fuzz("<polarform version=\"1\"><fit scan=\"a.ply\" method=\"cylindrical\" closed=\"no\" "
       "pole=\"cap\" degree=\"2,4\" tolerance=\"0.05\" tolerance-measure=\"p99\" "
       "center=\"1,2,3\" axis=\"0,0,1\" skip-bad=\"true\" fairness=\"fixed\" lambda=\"1e-4\" "
       "base=\"quartic\"/></polarform>",
       parse, 301, iterations());
}

#ifdef POLARFORM_HAVE_STUDIO_LOGIC
TEST(ParserFuzz, StudioScriptParserAcceptsOrRejectsCleanly) {
  const std::string seed =
      "# a session\nopen cams/roller.xml\ndrop a.xyz \"b c.ply\"\ntemplate vessel hemispherical\n"
      "workspace fit\nedit\nundo\nredo\nsave\nsave-as \"out/my cam.xml\"\n"
      "export all out\nscreenshot shot.png\nnumbers after\n";
  fuzz(seed,
       [](const std::string& text) {
         std::istringstream in(text);
         studio::parse_script(in, "/fuzz/script.txt");
       },
       400, iterations());
}
#endif

}  // namespace
}  // namespace polarform
