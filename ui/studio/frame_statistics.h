// Frame-time statistics for --bench-frames: every frame's wall time (edit, recomputation, drawing
// and buffer swap) and its parts — recomputing, building the UI (CPU), rendering it (OpenGL, to
// glFinish) — summarised as mean / median / p95 / max.
#pragma once

#include <string>
#include <vector>

namespace polarform::studio {

struct FrameTimes {  // milliseconds
  double frame = 0.0, compute = 0.0, ui = 0.0, render = 0.0;
};

struct TimeSummary {
  double mean = 0.0, median = 0.0, p95 = 0.0, max = 0.0, min = 0.0;  // milliseconds
};

// Nearest-rank statistics of the samples (milliseconds); zeros for none.
TimeSummary summarize(std::vector<double> milliseconds);

class FrameStatistics {
 public:
  void add(const FrameTimes& times);
  std::size_t frames() const { return frame_ms_.size(); }
  TimeSummary frame_times() const { return summarize(frame_ms_); }
  // Frames whose time exceeded `budget_ms`.
  std::size_t frames_over(double budget_ms) const;
  // "frames: N", then "frame time: mean … ms, median …, p95 …, max …, min …" and the same for the
  // recompute, UI and render parts, and the frames over the 60 fps budget.
  std::string text() const;

 private:
  std::vector<double> frame_ms_, compute_ms_, ui_ms_, render_ms_;
};

}  // namespace polarform::studio
