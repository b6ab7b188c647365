// Fuzz: 2000 deterministic random mutations (byte changes, bit flips, truncations, insertions of
// tricky tokens, deletions, duplicated slices, overwritten counts) of valid files of every format,
// each read by the sniffing entry point and by every per-format parser, with and without skip_bad.
// Only InputError may escape, its message names the file, every returned cloud holds at least 3
// finite points, and progress keeps its contract. The buffers are exactly sized heap blocks, so the
// ASan build (make asan) catches any read past the end.
#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "src/io/obj_reader.h"
#include "src/io/off_reader.h"
#include "src/io/ply_reader.h"
#include "src/io/point_cloud.h"
#include "src/io/stl_reader.h"
#include "src/io/xyz_reader.h"
#include "tests/support/src/sample_files.h"

namespace polarform {
namespace {

using io_test::PlyKind;

struct Seed {
  std::string name;
  std::string bytes;
};

std::vector<Seed> seeds() {
  const Eigen::Matrix3Xd p = io_test::sample_points();
  return {
      {"a.xyz", io_test::sample_xyz(p, false)},
      {"a.csv", io_test::sample_xyz(p, true)},
      {"a.pts", "6\n1 2 3 9\n4 5 6 9\n7 8 9 9\n1 1 1 9\n2 2 2 9\n3 3 3 9\n"},
      {"a.ply", io_test::sample_ply(p, PlyKind::ascii, false)},
      {"b.ply", io_test::sample_ply(p, PlyKind::binary_little_endian, false)},
      {"c.ply", io_test::sample_ply(p, PlyKind::binary_big_endian, true)},
      {"d.ply", io_test::sample_ply(p, PlyKind::binary_little_endian, true, false)},
      {"a.stl", io_test::ascii_stl(p)},
      {"b.stl", io_test::binary_stl(p, "binary")},
      {"c.stl", io_test::binary_stl(p, "solid binary")},
      {"a.obj", io_test::sample_obj(p)},
      {"a.off", io_test::sample_off(p, "CNOFF")},
      {"b.off", "4nOFF 3\n3 1 0\n2 4 6 2\n1 1 1 0.5\n-3 0 3 -1\n3 0 1 2\n"},
      {"noext", io_test::sample_ply(p, PlyKind::binary_big_endian, false)},
  };
}

const std::vector<std::string> kTokens = {"nan",
                                          "inf",
                                          "-inf",
                                          "1e999",
                                          "-1",
                                          "0",
                                          "4294967295",
                                          "18446744073709551616",
                                          "255",
                                          ",",
                                          "#",
                                          "\n",
                                          "\r\n",
                                          " ",
                                          "\t",
                                          ".",
                                          "e",
                                          "+",
                                          "-",
                                          std::string(1, '\0'),
                                          "\xff",
                                          "end_header\n",
                                          "element vertex 99999999999\n",
                                          "property list uchar int n\n",
                                          "solid ",
                                          "vertex ",
                                          "v ",
                                          "OFF",
                                          "nOFF 1000000000\n",
                                          "4OFF\n",
                                          "format binary_big_endian 1.0\n"};

std::vector<char> mutate(const std::string& seed, std::mt19937& rng) {
  std::vector<char> b(seed.begin(), seed.end());
  const auto below = [&](std::size_t n) {
    return n == 0 ? 0 : static_cast<std::size_t>(rng() % n);
  };
  const int rounds = 1 + static_cast<int>(rng() % 3);
  for (int r = 0; r < rounds; ++r) {
    const std::size_t at = below(b.size() + 1);
    switch (rng() % 7) {
      case 0:
        if (at < b.size()) b[at] = static_cast<char>(rng());
        break;
      case 1:
        if (at < b.size()) b[at] = static_cast<char>(b[at] ^ (1 << (rng() % 8)));
        break;
      case 2:
        b.resize(at);
        break;
      case 3: {
        const std::string& token = kTokens[below(kTokens.size())];
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(at), token.begin(), token.end());
        break;
      }
      case 4:
        b.erase(b.begin() + static_cast<std::ptrdiff_t>(at),
                b.begin() + static_cast<std::ptrdiff_t>(std::min(b.size(), at + 1 + below(16))));
        break;
      case 5: {
        const std::size_t from = below(b.size());
        const std::size_t length = std::min(b.size() - from, 1 + below(64));
        const std::vector<char> slice(b.begin() + static_cast<std::ptrdiff_t>(from),
                                      b.begin() + static_cast<std::ptrdiff_t>(from + length));
        b.insert(b.begin() + static_cast<std::ptrdiff_t>(at), slice.begin(), slice.end());
        break;
      }
      default: {
        static constexpr std::uint32_t counts[] = {0, 1, 2, 3, 0x7fffffff, 0x80000000, 0xffffffff};
        const std::uint32_t count = counts[below(std::size(counts))];
        for (std::size_t k = 0; k < 4 && at + k < b.size(); ++k)
          b[at + k] = static_cast<char>(count >> (8 * k));
      }
    }
  }
  return b;
}

using Parser = std::function<PointCloud(std::string_view, std::string_view, const ReadOptions&)>;

struct Tally {
  std::size_t accepted = 0;
  std::size_t rejected = 0;
};

void check(const Parser& parse, std::string_view bytes, const std::string& name, bool skip_bad,
           const std::string& label, Tally& tally) {
  std::vector<double> calls;
  ReadOptions options;
  options.skip_bad = skip_bad;
  options.progress = [&](double f) { calls.push_back(f); };
  try {
    const PointCloud cloud = parse(bytes, name, options);
    ++tally.accepted;
    EXPECT_GE(cloud.points.cols(), 3) << label;
    EXPECT_TRUE(cloud.points.allFinite()) << label;
    EXPECT_TRUE(skip_bad || cloud.dropped == 0) << label;
    EXPECT_TRUE(!calls.empty() && calls.back() == 1.0) << label;
  } catch (const InputError& e) {
    ++tally.rejected;
    EXPECT_TRUE(std::string_view(e.what()).starts_with(name)) << label << ": " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << label << ": threw something other than InputError: " << e.what();
  }
  EXPECT_LE(calls.size(), 100u) << label;
  for (std::size_t i = 1; i < calls.size(); ++i) EXPECT_GT(calls[i], calls[i - 1]) << label;
}

TEST(IoFuzz, MutatedFilesOnlyEverThrowInputError) {
  const std::vector<Seed> all = seeds();
  const std::vector<std::pair<std::string, Parser>> parsers = {
      {"sniffing", [](auto b, auto n, const auto& o) { return parse_point_cloud(b, n, o); }},
      {"xyz", [](auto b, auto n, const auto& o) { return parse_xyz(b, n, o); }},
      {"ply", [](auto b, auto n, const auto& o) { return parse_ply(b, n, o); }},
      {"stl", [](auto b, auto n, const auto& o) { return parse_stl(b, n, o); }},
      {"obj", [](auto b, auto n, const auto& o) { return parse_obj(b, n, o); }},
      {"off", [](auto b, auto n, const auto& o) { return parse_off(b, n, o); }}};
  constexpr int kMutations = 2000;
  Tally sniffed;
  Tally all_parsers;
  for (int m = 0; m < kMutations; ++m) {
    std::mt19937 rng(static_cast<std::uint32_t>(m));
    const Seed& seed = all[static_cast<std::size_t>(m) % all.size()];
    const std::vector<char> bytes = mutate(seed.bytes, rng);
    const std::string_view view(bytes.data(), bytes.size());
    for (const auto& [parser, parse] : parsers)
      for (const bool skip_bad : {false, true}) {
        const std::string label = "mutation " + std::to_string(m) + " of " + seed.name + " by " +
                                  parser + (skip_bad ? " with skip_bad" : "");
        check(parse, view, seed.name, skip_bad, label,
              parser == "sniffing" ? sniffed : all_parsers);
      }
  }
  // The mutations must exercise both outcomes, or the fuzz test proves nothing.
  EXPECT_GT(sniffed.accepted, kMutations / 4);
  EXPECT_GT(sniffed.rejected, kMutations / 4);
  EXPECT_EQ(sniffed.accepted + sniffed.rejected, 2u * kMutations);
  EXPECT_EQ(all_parsers.accepted + all_parsers.rejected, 10u * kMutations);
  std::printf(
      "fuzz: sniffing accepted %zu, rejected %zu; per-format parsers accepted %zu, rejected %zu\n",
      sniffed.accepted, sniffed.rejected, all_parsers.accepted, all_parsers.rejected);
}

}  // namespace
}  // namespace polarform
