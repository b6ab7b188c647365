#include "designers/convert/refined_maximum.h"

#include <algorithm>
#include <cmath>

#include "src/nurbs/brent_minimum.h"

namespace polarform {

namespace {

struct Sample {
  double t, value;
  double lo, hi;              // the neighbouring samples' abscissae (t itself at the grid's ends)
  double f_lo = 0, f_hi = 0;  // and values
};

}  // namespace

Maximum refined_maximum(const std::function<double(double)>& f, const std::vector<double>& grid,
                        int per_interval, int refine) {
  std::vector<Sample> samples;
  for (std::size_t i = 0; i + 1 < grid.size(); ++i) {
    const double a = grid[i], b = grid[i + 1], h = (b - a) / per_interval;
    if (!(b > a)) continue;
    for (int k = 0; k <= per_interval; ++k) {
      const double t = k == per_interval ? b : a + k * h;
      samples.push_back({t, f(t), t, t});
    }
  }
  Maximum best;
  if (samples.empty()) return best;
  // Candidates: the local maxima of the samples (each bump of f once), largest first, each
  // bracketed by its neighbours (an interval's end sample and the next one's start coincide).
  std::vector<Sample> peaks;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    Sample s = samples[k];
    s.f_lo = s.f_hi = s.value;
    std::size_t left = k, right = k;
    while (left > 0 && !(samples[left].t > samples[left - 1].t)) --left;
    if (left < k) continue;  // counted at its first copy
    while (right + 1 < samples.size() && !(samples[right + 1].t > samples[right].t)) ++right;
    const bool has_left = left > 0, has_right = right + 1 < samples.size();
    if (has_left && samples[left - 1].value > s.value) continue;
    if (has_right && samples[right + 1].value > s.value) continue;
    if (has_left) s.lo = samples[left - 1].t, s.f_lo = samples[left - 1].value;
    if (has_right) s.hi = samples[right + 1].t, s.f_hi = samples[right + 1].value;
    peaks.push_back(s);
  }
  const int count = std::min<int>(refine, static_cast<int>(peaks.size()));
  std::partial_sort(peaks.begin(), peaks.begin() + count, peaks.end(),
                    [](const Sample& x, const Sample& y) { return x.value > y.value; });
  best = {peaks.front().t, peaks.front().value};
  for (int k = 0; k < count; ++k) {
    // Brent minimises −f, from the peak and its neighbours, to 1e-4 of the bracket: near a
    // smooth peak the value's error goes with the square of that (refined_maximum_test: within
    // 1e-12 of a dense scan's), and the search takes about 6 evaluations instead of 12 at 1e-7
    // of the bracket, where round-off in f had it fall back on golden-section steps (measured on
    // the roller's conversion at 1 µm: 938 evaluations against 1741).
    const Sample& s = peaks[k];
    if (!(s.hi > s.lo)) continue;
    const BrentStart start{s.t, -s.value, -s.f_lo, -s.f_hi};
    const Minimum m =
        brent_minimum([&](double t) { return -f(t); }, s.lo, s.hi, 1e-4 * (s.hi - s.lo), &start);
    if (-m.value > best.value) best = {m.x, -m.value};
  }
  return best;
}

}  // namespace polarform
