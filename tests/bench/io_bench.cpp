// Reading 10^6 points: binary PLY with float coordinates (as scanners write it) and with double
// (as write_ply writes it), and ascii xyz with 6 decimals. The files are generated once into a
// temporary directory. Reports ms per read and MB/s. Budget: the scan pipeline has 2 s for 10^6
// points, so binary PLY should read in well under 0.3 s.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "export/ply_writer.h"
#include "src/io/point_cloud.h"

namespace polarform {
namespace {

namespace fs = std::filesystem;

constexpr int kPoints = 1'000'000;

// A noisy sphere of radius 50 mm, like a scanned reference ball.
Eigen::Matrix3Xd scan_points() {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Matrix3Xd points(3, kPoints);
  for (int i = 0; i < kPoints; ++i) {
    const Eigen::Vector3d d(normal(rng), normal(rng), normal(rng));
    points.col(i) = d.normalized() * (50.0 + 0.01 * normal(rng));
  }
  return points;
}

void write_float_ply(const fs::path& path, const Eigen::Matrix3Xd& points) {
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << points.cols()
      << "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  for (int i = 0; i < points.cols(); ++i)
    for (int k = 0; k < 3; ++k) {
      const auto f = static_cast<float>(points(k, i));
      out.write(reinterpret_cast<const char*>(&f), sizeof f);
    }
}

void write_xyz(const fs::path& path, const Eigen::Matrix3Xd& points) {
  std::string text;
  char number[32];
  for (int i = 0; i < points.cols(); ++i)
    for (int k = 0; k < 3; ++k) {
      text.append(number, std::to_chars(number, number + sizeof number, points(k, i),
                                        std::chars_format::fixed, 6)
                              .ptr);
      text += k < 2 ? ' ' : '\n';
    }
  std::ofstream(path, std::ios::binary) << text;
}

enum class File { ply_float, ply_double, xyz };

class BenchFiles {
 public:
  BenchFiles()
      : dir_(fs::temp_directory_path() / ("polarform_io_bench_" + std::to_string(::getpid()))) {
    fs::create_directories(dir_);
    const Eigen::Matrix3Xd points = scan_points();
    write_float_ply(path(File::ply_float), points);
    write_ply(path(File::ply_double), points);
    write_xyz(path(File::xyz), points);
  }
  ~BenchFiles() { fs::remove_all(dir_); }

  fs::path path(File file) const {
    return dir_ / (file == File::ply_float    ? "float.ply"
                   : file == File::ply_double ? "double.ply"
                                              : "scan.xyz");
  }

 private:
  fs::path dir_;
};

const BenchFiles& bench_files() {
  static const BenchFiles files;
  return files;
}

void BM_ReadPointCloud(benchmark::State& state, File file) {
  const fs::path path = bench_files().path(file);
  const auto bytes = static_cast<double>(fs::file_size(path));
  for (auto _ : state) {
    const PointCloud cloud = read_point_cloud(path);
    if (cloud.points.cols() != kPoints) state.SkipWithError("wrong point count");
    benchmark::DoNotOptimize(cloud.points.data());
  }
  state.counters["MB"] = bytes / 1e6;
  state.counters["MB/s"] =
      benchmark::Counter(bytes / 1e6, benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK_CAPTURE(BM_ReadPointCloud, ply_binary_float_1M, File::ply_float)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ReadPointCloud, ply_binary_double_1M, File::ply_double)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ReadPointCloud, xyz_ascii_1M, File::xyz)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace polarform
