// Error statistics of a fit: rms, mean, max and the 95th / 99th percentiles of |d| over per-point
// distances d. Every fitter reports these for the TRUE point-to-geometry distances it measured, so
// the numbers a user relies on are measured, never assumed (DESIGN §3).
#pragma once

#include <Eigen/Core>
#include <cstddef>

namespace polarform {

struct ErrorStats {
  std::size_t count = 0;
  double rms = 0.0;
  double mean = 0.0;  // mean of |d|
  double max = 0.0;
  double p95 = 0.0;   // nearest-rank percentiles of |d|
  double p99 = 0.0;
};

// Statistics of |d| over the entries of d (signed distances). Empty input gives all zeros.
ErrorStats error_stats(const Eigen::VectorXd& d);
// The same of a temporary, its magnitudes taken in place (no copy: 80 MB fewer at 10^7 points).
ErrorStats error_stats(Eigen::VectorXd&& d);

// The nearest-rank q-quantile (0 < q <= 1) of |d| over the entries of d, in O(n).
double abs_quantile(const Eigen::VectorXd& d, double q);

}  // namespace polarform
