#include "ui/cli/progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace polarform::cli {

namespace {

constexpr int kBarWidth = 30;
constexpr auto kMinInterval = std::chrono::milliseconds(50);

}  // namespace

ProgressBar::ProgressBar(std::string label, bool enabled)
    : label_(std::move(label)), active_(enabled && ::isatty(STDERR_FILENO) == 1) {}

ProgressBar::~ProgressBar() {
  if (active_ && drawn_) std::fputc('\n', stderr);
}

void ProgressBar::operator()(double fraction) {
  if (!active_ || !(fraction >= 0.0)) return;
  const int percent = static_cast<int>(std::floor(std::min(fraction, 1.0) * 100.0));
  if (percent <= percent_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_draw_ < kMinInterval) return;
  last_draw_ = now;
  draw(percent);
}

void ProgressBar::finish() {
  if (!active_) return;
  draw(100);
  std::fputc('\n', stderr);
  std::fflush(stderr);
  active_ = false;
}

void ProgressBar::draw(int percent) {
  percent_ = percent;
  drawn_ = true;
  const int filled = percent * kBarWidth / 100;
  std::fprintf(stderr, "\r%s [%s%s] %d%%", label_.c_str(), std::string(filled, '#').c_str(),
               std::string(kBarWidth - filled, ' ').c_str(), percent);
  std::fflush(stderr);
}

}  // namespace polarform::cli
