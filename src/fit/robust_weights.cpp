// Tukey's biweight on a MAD scale.
#include "src/fit/robust_weights.h"

#include <algorithm>
#include <cmath>

#include "src/fit/error_stats.h"

namespace polarform {

Eigen::VectorXd tukey_weights(const Eigen::VectorXd& residual, double floor) {
  const double mad = residual.size() ? abs_quantile(residual, 0.5) : 0.0;
  const double s = std::max(1.4826 * mad, floor);
  Eigen::VectorXd w(residual.size());
  for (Eigen::Index k = 0; k < residual.size(); ++k) {
    const double t = residual[k] / (4.685 * s);
    w[k] = std::abs(t) < 1.0 ? (1 - t * t) * (1 - t * t) : 0.0;
  }
  return w;
}

}  // namespace polarform
