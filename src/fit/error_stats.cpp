#include "src/fit/error_stats.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace polarform {

namespace {

// 1-based nearest rank of the q-quantile among n values.
std::size_t rank_of(double q, std::size_t n) {
  return std::clamp<std::size_t>(static_cast<std::size_t>(std::ceil(q * static_cast<double>(n))), 1, n);
}

// The value of 1-based rank r among a[0, end) (reordered in place).
double value_at_rank(std::vector<double>& a, std::size_t end, std::size_t r) {
  const auto k = a.begin() + static_cast<std::ptrdiff_t>(r - 1);
  std::nth_element(a.begin(), k, a.begin() + static_cast<std::ptrdiff_t>(end));
  return *k;
}

std::vector<double> absolute(const Eigen::VectorXd& d) {
  std::vector<double> a(static_cast<std::size_t>(d.size()));
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = std::abs(d[static_cast<Eigen::Index>(i)]);
  return a;
}

}  // namespace

double abs_quantile(const Eigen::VectorXd& d, double q) {
  if (d.size() == 0) return 0.0;
  std::vector<double> a = absolute(d);
  return value_at_rank(a, a.size(), rank_of(q, a.size()));
}

namespace {

// The statistics of the magnitudes a[0, n) (reordered in place).
ErrorStats magnitude_stats(double* a, std::size_t n) {
  ErrorStats s;
  s.count = n;
  if (n == 0) return s;
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sum += a[i];
    sum2 += a[i] * a[i];
    s.max = std::max(s.max, a[i]);
  }
  s.mean = sum / static_cast<double>(n);
  s.rms = std::sqrt(sum2 / static_cast<double>(n));
  const std::size_t r99 = rank_of(0.99, n), r95 = rank_of(0.95, n);
  std::nth_element(a, a + (r99 - 1), a + n);
  s.p99 = a[r99 - 1];
  std::nth_element(a, a + (r95 - 1), a + r99);  // a[0, r99) holds the r99 smallest
  s.p95 = a[r95 - 1];
  return s;
}

}  // namespace

ErrorStats error_stats(const Eigen::VectorXd& d) {
  if (d.size() == 0) return ErrorStats{};
  std::vector<double> a = absolute(d);
  return magnitude_stats(a.data(), a.size());
}

ErrorStats error_stats(Eigen::VectorXd&& d) {
  d = d.cwiseAbs();
  return magnitude_stats(d.data(), static_cast<std::size_t>(d.size()));
}

}  // namespace polarform
