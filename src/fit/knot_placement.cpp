#include "src/fit/knot_placement.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "src/error.h"

namespace polarform {

namespace {

std::vector<double> uniform_breaks(int spans, double a, double b) {
  std::vector<double> out(spans + 1);
  for (int s = 0; s < spans; ++s) out[s] = a + (b - a) * s / spans;
  out[spans] = b;
  return out;
}

// NURBS Book eq. (9.68)-(9.69) on the sorted parameters, here as quantiles k/spans of their
// distribution, interpolated linearly inside the bins of a histogram.
std::vector<double> quantile_breaks(int spans, const Eigen::VectorXd& params, double a, double b) {
  const std::size_t n = static_cast<std::size_t>(params.size());
  const int bins = static_cast<int>(std::clamp<std::size_t>(n / 4, 16, 1 << 16));
  std::vector<double> count(bins, 0.0);
  const double scale = bins / (b - a);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = (params[static_cast<Eigen::Index>(k)] - a) * scale;
    count[std::clamp(static_cast<int>(x), 0, bins - 1)] += 1.0;
  }
  std::vector<double> out = {a};
  double cum = 0.0;
  int bin = 0;
  for (int s = 1; s < spans; ++s) {
    const double target = static_cast<double>(n) * s / spans;
    while (bin < bins - 1 && cum + count[bin] < target) cum += count[bin++];
    const double frac = count[bin] > 0 ? std::clamp((target - cum) / count[bin], 0.0, 1.0) : 0.5;
    out.push_back(a + (bin + frac) / scale);
  }
  out.push_back(b);
  return out;
}

// Clamps every span width into [lo, hi] (lo·spans <= b − a <= hi·spans) by alternating forward
// and backward sweeps, which keeps the breaks sorted and the ends fixed.
void clamp_spans(std::vector<double>& br, double lo, double hi) {
  const std::size_t k = br.size() - 1;
  for (int sweep = 0; sweep < 4; ++sweep) {
    for (std::size_t s = 1; s < k; ++s) br[s] = std::clamp(br[s], br[s - 1] + lo, br[s - 1] + hi);
    for (std::size_t s = k - 1; s >= 1; --s) br[s] = std::clamp(br[s], br[s + 1] - hi, br[s + 1] - lo);
  }
}

}  // namespace

std::vector<double> place_breaks(KnotPlacement placement, int spans, const Eigen::VectorXd& params,
                                 double a, double b) {
  if (spans < 1) throw InputError("knot placement: " + std::to_string(spans) + " spans, expected >= 1");
  if (!(std::isfinite(a) && std::isfinite(b) && a < b))
    throw InputError("knot placement: domain [" + std::to_string(a) + ", " + std::to_string(b) +
                     "], expected finite a < b");
  if (placement == KnotPlacement::uniform || spans == 1 || params.size() == 0)
    return uniform_breaks(spans, a, b);
  std::vector<double> br = quantile_breaks(spans, params, a, b);
  const double h = (b - a) / spans;
  clamp_spans(br, 0.5 * h, 2.0 * h);
  return br;
}

std::vector<double> split_spans(const std::vector<double>& breaks, const std::vector<bool>& split) {
  if (split.size() + 1 != breaks.size())
    throw InputError("split_spans: " + std::to_string(split.size()) + " flags for " +
                     std::to_string(breaks.size() - 1) + " spans");
  std::vector<double> out = {breaks.front()};
  for (std::size_t s = 0; s + 1 < breaks.size(); ++s) {
    if (split[s]) out.push_back(0.5 * (breaks[s] + breaks[s + 1]));
    out.push_back(breaks[s + 1]);
  }
  return out;
}

int span_index(const std::vector<double>& breaks, double x) {
  const auto it = std::upper_bound(breaks.begin() + 1, breaks.end() - 1, x);
  return static_cast<int>(it - breaks.begin()) - 1;
}

}  // namespace polarform
