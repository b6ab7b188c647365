// Azimuthal coverage of meridian cells: the points a surface of revolution can explain.
#include "designers/sweep/azimuthal_coverage.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>

namespace polarform {

AzimuthalCoverage azimuthal_coverage(const Eigen::Matrix3Xd& P, const AxisLine& axis, double cell,
                                     int sectors) {
  const auto [e1, e2] = normal_pair(axis.direction);
  const Eigen::Index n = P.cols();
  std::vector<std::int64_t> key(static_cast<std::size_t>(n));
  struct Cell {
    std::uint64_t sectors = 0;
    int count = 0;
    double ratio = 0.0;  // distinct sectors / those `count` random points would cover
  };
  std::unordered_map<std::int64_t, Cell> cells;
  sectors = std::clamp(sectors, 2, 64);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Vector3d w = P.col(k) - axis.point;
    const double z = w.dot(axis.direction), x = w.dot(e1), y = w.dot(e2);
    const double r = std::hypot(x, y), t = std::atan2(y, x) + std::numbers::pi;
    const std::int64_t iz = static_cast<std::int64_t>(std::floor(z / cell)),
                       ir = static_cast<std::int64_t>(std::floor(r / cell));
    key[k] = (iz << 32) ^ ir;
    const int sector =
        std::min(sectors - 1, static_cast<int>(t / (2 * std::numbers::pi) * sectors));
    Cell& c = cells[key[k]];
    c.sectors |= std::uint64_t{1} << sector;
    ++c.count;
  }
  for (auto& [k, c] : cells)
    c.ratio = std::popcount(c.sectors) / (sectors * (1 - std::pow(1 - 1.0 / sectors, c.count)));
  std::vector<double> ratios(static_cast<std::size_t>(n));
  for (Eigen::Index k = 0; k < n; ++k) ratios[k] = cells.find(key[k])->second.ratio;
  AzimuthalCoverage out;
  std::vector<double> sorted = ratios;
  std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
  out.median_ratio = n ? sorted[static_cast<std::size_t>(n / 2)] : 0.0;
  out.rotational.resize(static_cast<std::size_t>(n));
  for (Eigen::Index k = 0; k < n; ++k) {
    out.rotational[k] = ratios[k] >= 0.5 * out.median_ratio;
    out.set_aside += !out.rotational[k];
  }
  return out;
}

}  // namespace polarform
