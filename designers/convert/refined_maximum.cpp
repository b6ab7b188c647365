#include "designers/convert/refined_maximum.h"

#include <algorithm>
#include <cmath>

namespace polarform {

namespace {

struct Sample {
  double t, value;
  double lo, hi;              // the neighbouring samples' abscissae (t itself at the grid's ends)
  double f_lo = 0, f_hi = 0;  // and values
};

// Brent's method (Brent 1973, "localmin") for the maximum of f on [a, b], started at the sample
// x (with f(x) = fx >= f at the ends a and b) with the ends as the two previous points, so that
// the first step is the parabola through the three samples.
Maximum brent_maximum(const std::function<double(double)>& f, const Sample& s) {
  constexpr double kGolden = 0.3819660112501051;  // (3 − √5)/2
  constexpr int kSteps = 40;
  double a = s.lo, b = s.hi, x = s.t, fx = s.value;
  // Brent minimises: g = −f.
  double w = a, gw = -s.f_lo, v = b, gv = -s.f_hi, gx = -fx;
  if (!(b > a)) return {x, fx};
  const double tol = 1e-7 * (b - a);
  // The step before last as large as the bracket, so that the first parabola is tried.
  double d = b - a, e = b - a;
  for (int step = 0; step < kSteps; ++step) {
    const double xm = 0.5 * (a + b);
    if (std::abs(x - xm) <= 2 * tol - 0.5 * (b - a)) break;
    bool golden = true;
    if (std::abs(e) > tol) {  // a parabola through x, w, v
      double r = (x - w) * (gx - gv), q = (x - v) * (gx - gw), p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p;
      q = std::abs(q);
      const double last = e;
      e = d;
      if (std::abs(p) < std::abs(0.5 * q * last) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        const double u = x + d;
        if (u - a < 2 * tol || b - u < 2 * tol) d = xm >= x ? tol : -tol;
        golden = false;
      }
    }
    if (golden) {
      e = x >= xm ? a - x : b - x;
      d = kGolden * e;
    }
    const double u = x + (std::abs(d) >= tol ? d : (d > 0 ? tol : -tol));
    const double gu = -f(u);
    if (gu <= gx) {
      (u >= x ? a : b) = x;
      v = w, gv = gw, w = x, gw = gx, x = u, gx = gu;
    } else {
      (u < x ? a : b) = u;
      if (gu <= gw || w == x) {
        v = w, gv = gw, w = u, gw = gu;
      } else if (gu <= gv || v == x || v == w) {
        v = u, gv = gu;
      }
    }
  }
  return {x, -gx};
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
    const Maximum m = brent_maximum(f, peaks[k]);
    if (m.value > best.value) best = m;
  }
  return best;
}

}  // namespace polarform
