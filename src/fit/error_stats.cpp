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

ErrorStats error_stats(const Eigen::VectorXd& d) {
  ErrorStats s;
  s.count = static_cast<std::size_t>(d.size());
  if (s.count == 0) return s;
  std::vector<double> a = absolute(d);
  double sum = 0.0, sum2 = 0.0;
  for (double x : a) {
    sum += x;
    sum2 += x * x;
    s.max = std::max(s.max, x);
  }
  s.mean = sum / static_cast<double>(s.count);
  s.rms = std::sqrt(sum2 / static_cast<double>(s.count));
  const std::size_t r99 = rank_of(0.99, s.count), r95 = rank_of(0.95, s.count);
  s.p99 = value_at_rank(a, s.count, r99);
  s.p95 = value_at_rank(a, r99, r95);  // after the first pass a[0, r99) holds the r99 smallest
  return s;
}

}  // namespace polarform
