#include "ui/studio/frame_statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace polarform::studio {
namespace {

std::string summary_text(const TimeSummary& s) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer,
                "mean %.2f ms, median %.2f ms, p95 %.2f ms, max %.2f ms, min %.2f ms", s.mean,
                s.median, s.p95, s.max, s.min);
  return buffer;
}

}  // namespace

TimeSummary summarize(std::vector<double> ms) {
  TimeSummary s;
  if (ms.empty()) return s;
  std::sort(ms.begin(), ms.end());
  const auto rank = [&](double q) {
    const auto k = static_cast<std::size_t>(std::ceil(q * static_cast<double>(ms.size())));
    return ms[std::clamp<std::size_t>(k, 1, ms.size()) - 1];
  };
  s.mean = std::accumulate(ms.begin(), ms.end(), 0.0) / static_cast<double>(ms.size());
  s.median = rank(0.5);
  s.p95 = rank(0.95);
  s.max = ms.back();
  s.min = ms.front();
  return s;
}

void FrameStatistics::add(const FrameTimes& times) {
  frame_ms_.push_back(times.frame);
  compute_ms_.push_back(times.compute);
  ui_ms_.push_back(times.ui);
  render_ms_.push_back(times.render);
}

std::size_t FrameStatistics::frames_over(double budget_ms) const {
  return static_cast<std::size_t>(
      std::count_if(frame_ms_.begin(), frame_ms_.end(), [&](double t) { return t > budget_ms; }));
}

std::string FrameStatistics::text() const {
  return "frames: " + std::to_string(frames()) + "\nframe time: " + summary_text(frame_times()) +
         "\nrecompute time: " + summary_text(summarize(compute_ms_)) +
         "\nui time: " + summary_text(summarize(ui_ms_)) +
         "\nrender time: " + summary_text(summarize(render_ms_)) +
         "\nframes over 16.7 ms: " + std::to_string(frames_over(1000.0 / 60.0)) + "\n";
}

}  // namespace polarform::studio
