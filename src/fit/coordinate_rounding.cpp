#include "src/fit/coordinate_rounding.h"

#include <cmath>
#include <limits>

namespace polarform {

double coordinate_rounding(const Eigen::Matrix3Xd& points) {
  bool single = true;
  double largest = 0.0;
  for (Eigen::Index k = 0; k < points.size(); ++k) {
    const double x = points.data()[k];
    single = single && static_cast<double>(static_cast<float>(x)) == x;
    largest = std::max(largest, std::abs(x));
  }
  const double eps =
      single ? std::numeric_limits<float>::epsilon() : std::numeric_limits<double>::epsilon();
  return 0.5 * eps * largest;
}

}  // namespace polarform
