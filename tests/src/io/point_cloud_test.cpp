// read_point_cloud: format detection (signatures over extensions, extensions over sniffing),
// files on disk (memory-mapped), file-level errors, and the progress callback contract.
#include "src/io/point_cloud.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "tests/support/src/sample_files.h"

namespace polarform {
namespace {

namespace fs = std::filesystem;
using io_test::input_error;
using io_test::PlyKind;
using ::testing::HasSubstr;

class TempDir {
 public:
  TempDir()
      : path_(fs::temp_directory_path() / ("polarform_io_test_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  fs::path write(const std::string& name, const std::string& content) const {
    std::ofstream(path_ / name, std::ios::binary) << content;
    return path_ / name;
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

TEST(PointCloud, SignaturesOverrideTheExtension) {
  const Eigen::Matrix3Xd p = io_test::sample_points();
  const std::string ply = io_test::sample_ply(p, PlyKind::binary_little_endian, false);
  const std::string stl = io_test::binary_stl(p, "solid but binary");
  EXPECT_EQ(detect_cloud_format("scan.stl", ply), CloudFormat::ply);
  EXPECT_EQ(detect_cloud_format("scan.txt", stl), CloudFormat::stl);
  EXPECT_EQ(detect_cloud_format("scan.xyz", io_test::sample_off(p, "COFF")), CloudFormat::off);
  EXPECT_EQ(detect_cloud_format("scan.ply", "1 2 3\n"), CloudFormat::ply);
  EXPECT_EQ(detect_cloud_format("SCAN.OBJ", "1 2 3\n"), CloudFormat::obj);
  EXPECT_EQ(detect_cloud_format("mesh.off", "3 1 0\n"), CloudFormat::off);
  EXPECT_EQ(detect_cloud_format("scan", io_test::sample_obj(p)), CloudFormat::obj);
  EXPECT_EQ(detect_cloud_format("scan.dat", io_test::ascii_stl(p)), CloudFormat::stl);
  EXPECT_EQ(detect_cloud_format("scan.dat", io_test::sample_xyz(p, true)), CloudFormat::xyz);
  EXPECT_EQ(detect_cloud_format("points", "1 2 3\n4 5 6\n"), CloudFormat::xyz);
  // A lying extension still reads the right points.
  EXPECT_EQ(parse_point_cloud(ply, "scan.stl").points, p);
  EXPECT_EQ(parse_point_cloud(stl, "scan.txt").points, p);
}

TEST(PointCloud, ReadsFilesOfEveryFormat) {
  const TempDir dir;
  const Eigen::Matrix3Xd p = io_test::sample_points();
  const std::vector<std::pair<std::string, std::string>> files = {
      {"a.xyz", io_test::sample_xyz(p, false)},
      {"a.csv", io_test::sample_xyz(p, true)},
      {"a.ply", io_test::sample_ply(p, PlyKind::binary_big_endian, true)},
      {"b.ply", io_test::sample_ply(p, PlyKind::ascii, false)},
      {"a.stl", io_test::binary_stl(p, "solid")},
      {"b.stl", io_test::ascii_stl(p)},
      {"a.obj", io_test::sample_obj(p)},
      {"a.off", io_test::sample_off(p)},
      {"no_extension", io_test::sample_ply(p, PlyKind::binary_little_endian, false)}};
  for (const auto& [name, content] : files) {
    SCOPED_TRACE(name);
    EXPECT_EQ(read_point_cloud(dir.write(name, content)).points, p);
  }
}

TEST(PointCloud, FileErrors) {
  const TempDir dir;
  EXPECT_THAT(input_error([&] { read_point_cloud(dir.path() / "missing.ply"); }),
              HasSubstr("missing.ply: cannot open file: No such file or directory"));
  EXPECT_THAT(input_error([&] { read_point_cloud(dir.write("empty.xyz", "")); }),
              HasSubstr("empty.xyz: file is empty"));
  EXPECT_THAT(input_error([&] { read_point_cloud(dir.path()); }), HasSubstr("not a regular file"));
  const fs::path bad = dir.write("bad.xyz", "1 2 3\n4 5 6\n7 8 9\n10 eleven 12\n");
  EXPECT_THAT(input_error([&] { read_point_cloud(bad); }),
              HasSubstr(bad.string() + ": line 4: invalid number 'eleven'"));
}

// Progress: increasing fractions in (0, 1], ending at 1, at most 100 calls.
std::vector<double> progress_of(const std::string& bytes, const std::string& name) {
  std::vector<double> calls;
  ReadOptions options;
  options.progress = [&](double f) { calls.push_back(f); };
  parse_point_cloud(bytes, name, options);
  return calls;
}

void expect_progress_contract(const std::vector<double>& calls, std::size_t at_least) {
  ASSERT_FALSE(calls.empty());
  EXPECT_LE(calls.size(), 100u);
  EXPECT_GE(calls.size(), at_least);
  EXPECT_GT(calls.front(), 0.0);
  EXPECT_EQ(calls.back(), 1.0);
  for (std::size_t i = 1; i < calls.size(); ++i) EXPECT_GT(calls[i], calls[i - 1]);
}

TEST(PointCloud, ProgressIsReportedAtMostAHundredTimes) {
  Eigen::Matrix3Xd many = Eigen::Matrix3Xd::Zero(3, 30000);
  for (int i = 0; i < many.cols(); ++i) many.col(i) = Eigen::Vector3d(i, 0.5 * i, -0.25 * i);
  // Every whole percent is crossed by some record, so each is reported once.
  expect_progress_contract(progress_of(io_test::sample_xyz(many, false), "m.xyz"), 100);
  expect_progress_contract(
      progress_of(io_test::sample_ply(many, PlyKind::binary_little_endian, false), "m.ply"), 100);
  expect_progress_contract(progress_of(io_test::sample_ply(many, PlyKind::ascii, true), "m.ply"),
                           100);
  expect_progress_contract(progress_of(io_test::binary_stl(many, ""), "m.stl"), 100);
  expect_progress_contract(progress_of(io_test::sample_obj(many), "m.obj"), 100);
  expect_progress_contract(progress_of(io_test::sample_off(many), "m.off"), 99);
  // A tiny file jumps straight to the end.
  const std::vector<double> small = progress_of("1 2 3\n4 5 6\n7 8 9\n", "s.xyz");
  ASSERT_EQ(small.size(), 3u);
  EXPECT_NEAR(small[0], 6.0 / 18.0, 1e-15);
  EXPECT_EQ(small[2], 1.0);
}

}  // namespace
}  // namespace polarform
