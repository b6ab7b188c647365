#include "designers/convert/golden_section.h"

#include <algorithm>

namespace polarform {

namespace {

struct Sample {
  double t, value, lo, hi;
};

// Golden-section search for the maximum of f on [lo, hi]; Kiefer 1953.
Maximum golden_maximum(const std::function<double(double)>& f, double lo, double hi) {
  constexpr double g = 0.6180339887498949;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = f(x1), f2 = f(x2);
  for (int it = 0; it < 16; ++it) {
    if (f1 > f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - g * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + g * (hi - lo), f2 = f(x2);
    }
  }
  return f1 > f2 ? Maximum{x1, f1} : Maximum{x2, f2};
}

}  // namespace

Maximum refined_maximum(const std::function<double(double)>& f, const std::vector<double>& grid,
                        int per_interval, int refine) {
  std::vector<Sample> samples;
  for (std::size_t i = 0; i + 1 < grid.size(); ++i) {
    const double a = grid[i], b = grid[i + 1], h = (b - a) / per_interval;
    if (!(b > a)) continue;
    for (int k = 0; k <= per_interval; ++k) {
      const double t = k == per_interval ? b : a + k * h;
      samples.push_back({t, f(t), std::max(a, t - h), std::min(b, t + h)});
    }
  }
  Maximum best;
  if (samples.empty()) return best;
  // Candidates: the local maxima of the samples (each bump of f once), largest first.
  std::vector<Sample> peaks;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const bool left = k == 0 || samples[k].value >= samples[k - 1].value;
    const bool right = k + 1 == samples.size() || samples[k].value >= samples[k + 1].value;
    if (left && right) peaks.push_back(samples[k]);
  }
  const int count = std::min<int>(refine, static_cast<int>(peaks.size()));
  std::partial_sort(peaks.begin(), peaks.begin() + count, peaks.end(),
                    [](const Sample& x, const Sample& y) { return x.value > y.value; });
  best = {peaks.front().t, peaks.front().value};
  for (int k = 0; k < count; ++k) {
    const Maximum m = golden_maximum(f, peaks[k].lo, peaks[k].hi);
    if (m.value > best.value) best = m;
  }
  return best;
}

}  // namespace polarform
