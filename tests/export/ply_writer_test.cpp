// write_ply: binary and ascii files read back bit for bit through the PLY reader, colours and the
// scalar land where the header says, and bad arguments are rejected before anything is written.
#include "export/ply_writer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "src/io/ply_header.h"
#include "src/io/point_cloud.h"
#include "tests/support/src/sample_files.h"

namespace polarform {
namespace {

namespace fs = std::filesystem;
using io_test::input_error;
using ::testing::HasSubstr;

struct Deviation {
  Eigen::Matrix3Xd points;
  std::vector<std::array<unsigned char, 3>> colors;
  std::vector<double> distance;
};

Deviation random_deviation(int n) {
  std::mt19937 rng(42);
  std::normal_distribution<double> normal(0.0, 50.0);
  Deviation d{Eigen::Matrix3Xd(3, n), {}, {}};
  for (int i = 0; i < n; ++i) {
    d.points.col(i) = Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    d.distance.push_back(normal(rng) * 1e-3);
    d.colors.push_back(
        {static_cast<unsigned char>(i), static_cast<unsigned char>(255 - i % 256), 7});
  }
  return d;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class PlyWriter : public ::testing::Test {
 protected:
  PlyWriter()
      : dir_(fs::temp_directory_path() / ("polarform_ply_writer_" + std::to_string(::getpid()))) {
    fs::create_directories(dir_);
  }
  ~PlyWriter() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(PlyWriter, BinaryRoundTripIsExactAndLaidOutAsDeclared) {
  const Deviation d = random_deviation(1000);
  const fs::path file = dir_ / "deviation.ply";
  write_ply(file, d.points, &d.colors, &d.distance, "distance");
  const PointCloud cloud = read_point_cloud(file);
  EXPECT_EQ(cloud.points, d.points);

  const std::string bytes = slurp(file);
  const PlyHeader header = parse_ply_header(bytes, "deviation.ply");
  EXPECT_EQ(header.storage, PlyStorage::binary_little_endian);
  ASSERT_EQ(header.elements.size(), 1u);
  ASSERT_EQ(header.elements[0].properties.size(), 7u);
  EXPECT_EQ(header.elements[0].properties[6].name, "distance");
  EXPECT_EQ(header.elements[0].properties[6].type, PlyType::float64);
  constexpr std::size_t kRecord = 3 * 8 + 3 + 8;
  EXPECT_EQ(bytes.size(), header.data_offset + 1000 * kRecord);
  for (const int i : {0, 7, 999}) {
    const char* record = bytes.data() + header.data_offset + i * kRecord;
    EXPECT_EQ(static_cast<unsigned char>(record[24]), d.colors[i][0]);
    EXPECT_EQ(static_cast<unsigned char>(record[25]), d.colors[i][1]);
    EXPECT_EQ(static_cast<unsigned char>(record[26]), 7);
    std::string expected;
    io_test::put<double>(expected, d.distance[i], false);
    EXPECT_EQ(std::string(record + 27, 8), expected);
  }
}

TEST_F(PlyWriter, AsciiRoundTripIsExact) {
  const Deviation d = random_deviation(200);
  const fs::path file = dir_ / "ascii.ply";
  write_ply(file, d.points, &d.colors, &d.distance, "signed_distance", false);
  EXPECT_EQ(read_point_cloud(file).points, d.points);
  const std::string bytes = slurp(file);
  EXPECT_THAT(bytes, HasSubstr("format ascii 1.0\n"));
  EXPECT_THAT(bytes, HasSubstr("property double signed_distance\nend_header\n"));
  write_ply(file, d.points);
  EXPECT_EQ(read_point_cloud(file).points, d.points);
  EXPECT_EQ(slurp(file).size(), parse_ply_header(slurp(file), "f").data_offset + 200 * 24);
}

TEST_F(PlyWriter, RejectsBadArgumentsAndKeepsTheOldFile) {
  const Deviation d = random_deviation(10);
  const fs::path file = dir_ / "keep.ply";
  write_ply(file, d.points);
  const std::string before = slurp(file);
  std::vector<std::array<unsigned char, 3>> short_colors(d.colors.begin(), d.colors.begin() + 9);
  EXPECT_THAT(input_error([&] { write_ply(file, d.points, &short_colors); }),
              HasSubstr("keep.ply: 9 colours for 10 points"));
  const std::vector<double> short_values(3, 0.0);
  EXPECT_THAT(input_error([&] { write_ply(file, d.points, nullptr, &short_values, "d"); }),
              HasSubstr("keep.ply: 3 values of 'd' for 10 points"));
  EXPECT_THAT(
      input_error([&] { write_ply(file, d.points, nullptr, &d.distance, "signed distance"); }),
      HasSubstr("scalar property name 'signed distance'"));
  EXPECT_THAT(input_error([&] { write_ply(file, d.points, nullptr, &d.distance, "z"); }),
              HasSubstr("scalar property name 'z'"));
  Eigen::Matrix3Xd nan = d.points;
  nan(2, 4) = std::nan("");
  EXPECT_THAT(input_error([&] { write_ply(file, nan); }),
              HasSubstr("keep.ply: point 4 has a NaN or infinite coordinate"));
  EXPECT_EQ(slurp(file), before);
  EXPECT_THAT(input_error([&] { write_ply(dir_ / "no" / "dir.ply", d.points); }),
              HasSubstr("does not exist"));
}

}  // namespace
}  // namespace polarform
