#include "designers/scan/motion_segmentation.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "src/error.h"

namespace polarform {

namespace {

constexpr int kGrid = 3600;             // cam angles tabulated over a revolution (0.1°)
constexpr int kHalfWindow = 10;         // ±1°: the span over which a still angle's ŝ is ranged
constexpr int kMinDwell = 20;           // grid steps: the shortest dwell, 2°
constexpr double kZ = 3.0;              // the band's half-width in standard errors
constexpr double kConfidence = 0.9973;  // P(|N(0,1)| <= 3)
constexpr double kMinBand = 1e-6;       // mm: the band of a noiseless scan (spline round-off)
constexpr double kStep = 2 * std::numbers::pi / kGrid;

// A run of grid indices [first, last] (unwrapped: last may pass kGrid) at one level.
struct Run {
  int first = 0, last = 0;
  double level = 0.0;
  bool dwell = true;
};

class Table {
 public:
  explicit Table(const ScannedCam& scan) : y_(kGrid) {
    for (int i = 0; i < kGrid; ++i)
      y_[static_cast<std::size_t>(i)] = scan.displacement.height(kStep * i);
  }
  double operator[](int i) const {
    return y_[static_cast<std::size_t>(((i % kGrid) + kGrid) % kGrid)];
  }
  double mean(int first, int last) const {
    double sum = 0.0;
    for (int i = first; i <= last; ++i) sum += (*this)[i];
    return sum / (last - first + 1);
  }

 private:
  std::vector<double> y_;
};

// Dwells: cyclic runs of still angles at least kMinDwell long, in increasing start.
std::vector<Run> dwell_runs(const Table& y, double band) {
  std::vector<bool> still(kGrid);
  for (int i = 0; i < kGrid; ++i) {
    double lo = INFINITY, hi = -INFINITY;
    for (int k = -kHalfWindow; k <= kHalfWindow; ++k)
      lo = std::min(lo, y[i + k]), hi = std::max(hi, y[i + k]);
    still[static_cast<std::size_t>(i)] = hi - lo <= band;
  }
  const auto at = [&](int i) {
    return static_cast<bool>(still[static_cast<std::size_t>(((i % kGrid) + kGrid) % kGrid)]);
  };
  if (std::all_of(still.begin(), still.end(), [](bool b) { return b; }))
    throw InputError(
        "design recovery: the follower does not move (the recovered displacement stays "
        "within its noise band over the whole revolution)");
  int origin = 0;  // a moving angle: runs are collected from there, so none is cut in two
  while (at(origin)) ++origin;
  std::vector<Run> runs;
  for (int i = origin + 1; i <= origin + kGrid; ++i) {
    if (!at(i) || at(i - 1)) continue;
    int j = i;
    while (at(j + 1) && j + 1 < origin + kGrid) ++j;
    if (j - i + 1 >= kMinDwell) {
      const int first = i % kGrid;
      runs.push_back(Run{first, first + (j - i), y.mean(i, j), true});
    }
    i = j;
  }
  std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.first < b.first; });
  return runs;
}

// The reversal points between grid indices a < b: where ŝ turns back by more than the band
// (hysteresis), and whether ŝ moved by more than the band at all.
std::vector<Run> reversals(const Table& y, int a, int b, double band, bool& moved) {
  std::vector<Run> out;
  int dir = 0, ext = a;
  for (int i = a; i <= b; ++i) {
    if (dir == 0) {
      if (std::abs(y[i] - y[a]) > band) dir = y[i] > y[a] ? 1 : -1, ext = i;
    } else if (dir * (y[i] - y[ext]) > 0) {
      ext = i;
    } else if (dir * (y[ext] - y[i]) > band) {
      out.push_back(Run{ext, ext, y[ext], false});
      dir = -dir, ext = i;
    }
  }
  moved = dir != 0;
  return out;
}

}  // namespace

MotionSegmentation segment_motion(const ScannedCam& scan) {
  MotionSegmentation m;
  m.still_band = std::max(2 * kZ * scan.displacement.standard_error, kMinBand);
  m.confidence = kConfidence;
  const Table y(scan);
  std::vector<Run> dwells = dwell_runs(y, m.still_band);
  if (dwells.empty()) {
    int lowest = 0;
    for (int i = 1; i < kGrid; ++i)
      if (y[i] < y[lowest]) lowest = i;
    dwells.push_back(Run{lowest, lowest, y[lowest], false});
  }
  // Dwells joined by no motion are one dwell (a noise excursion split it).
  for (std::size_t k = 0; dwells.size() > 1 && k < dwells.size();) {
    const std::size_t next = (k + 1) % dwells.size();
    const int b = dwells[next].first + (next <= k ? kGrid : 0);
    bool moved = false;
    reversals(y, dwells[k].last, b, m.still_band, moved);
    if (moved) {
      ++k;
      continue;
    }
    const int last = dwells[next].last + (next <= k ? kGrid : 0);
    dwells[k].level = y.mean(dwells[k].first, last);
    dwells[k].last = last;
    dwells.erase(dwells.begin() + static_cast<std::ptrdiff_t>(next));
    if (next < k) --k;
  }
  std::vector<Run> anchors;
  for (std::size_t k = 0; k < dwells.size(); ++k) {
    anchors.push_back(dwells[k]);
    const std::size_t next = (k + 1) % dwells.size();
    const int b = dwells[next].first + (next <= k ? kGrid : 0);
    bool moved = false;
    for (Run r : reversals(y, dwells[k].last, b, m.still_band, moved)) anchors.push_back(r);
    if (!moved)
      throw InputError(
          "design recovery: the follower does not move (the recovered displacement "
          "stays within its noise band over the whole revolution)");
  }
  for (Run& r : anchors) {
    const int shift = ((r.first % kGrid) + kGrid) % kGrid - r.first;
    r.first += shift, r.last += shift;
  }
  std::stable_sort(anchors.begin(), anchors.end(),
                   [](const Run& a, const Run& b) { return a.first < b.first; });
  for (std::size_t k = 0; k < anchors.size(); ++k) {
    const Run& a = anchors[k];
    const std::size_t next = (k + 1) % anchors.size();
    Run b = anchors[next];
    while (b.first < a.last || (next == k && b.first == a.first)) b.first += kGrid, b.last += kGrid;
    m.anchors.push_back(DwellRun{kStep * a.first, kStep * a.last, a.level});
    m.is_dwell.push_back(a.dwell);
    MotionPiece p;
    p.start = kStep * a.last, p.end = kStep * b.first;
    p.start_level = a.level, p.end_level = b.level;
    p.window_start = kStep * 0.5 * (a.first + a.last);
    p.window_end = kStep * 0.5 * (b.first + b.last);
    p.before = k, p.after = next;
    if (p.start >= 2 * std::numbers::pi) {
      for (double* t : {&p.start, &p.end, &p.window_start, &p.window_end})
        *t -= 2 * std::numbers::pi;
    }
    m.motions.push_back(p);
  }
  return m;
}

}  // namespace polarform
