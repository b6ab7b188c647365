#include "src/fit/coordinate_rounding.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace polarform {

namespace {

// The coarsest decimal quantum 10^-d (d from -3 to 17) of which x is a whole multiple.
double decimal_quantum(double x) {
  for (int d = -3; d <= 17; ++d) {
    const double scaled = x * std::pow(10.0, d);
    if (std::abs(scaled - std::round(scaled)) <= 1e-6 * std::max(1.0, 1e-9 * std::abs(scaled)))
      return std::pow(10.0, -d);
  }
  return 0.0;
}

}  // namespace

double coordinate_rounding(const Eigen::Matrix3Xd& points) {
  bool single = true;
  double largest = 0.0;
  for (Eigen::Index k = 0; k < points.size(); ++k) {
    const double x = points.data()[k];
    single = single && static_cast<double>(static_cast<float>(x)) == x;
    largest = std::max(largest, std::abs(x));
  }
  if (single) return 0.5 * std::numeric_limits<float>::epsilon() * largest;
  const double floor = 0.5 * std::numeric_limits<double>::epsilon() * largest;
  constexpr Eigen::Index kSubset = 30000;
  const Eigen::Index stride = std::max<Eigen::Index>(1, points.size() / kSubset);
  std::vector<double> quanta;
  for (Eigen::Index k = 0; k < points.size(); k += stride)
    if (points.data()[k] != 0.0) quanta.push_back(decimal_quantum(points.data()[k]));
  if (quanta.empty()) return floor;
  // The quantum 99 % of them are whole multiples of: the 1st percentile of each one's coarsest
  // (a coordinate that happens to end in zeros, or is constant on a ring, is a multiple of a
  // coarser one too).
  const auto q01 = quanta.begin() + static_cast<std::ptrdiff_t>(0.01 * double(quanta.size() - 1));
  std::nth_element(quanta.begin(), q01, quanta.end());
  return std::max(floor, 0.5 * *q01);
}

}  // namespace polarform
