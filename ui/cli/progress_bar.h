// A one-line progress bar on stderr, "label [#####     ] 42%", redrawn in place with '\r'. It
// draws only when enabled (the CLI passes !--quiet) and stderr is a terminal, so logs and pipes
// stay clean; redraws are limited to whole-percent changes at most every 50 ms.
#pragma once

#include <chrono>
#include <string>

namespace polarform::cli {

class ProgressBar {
 public:
  ProgressBar(std::string label, bool enabled);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // Shows `fraction` done (clamped to [0, 1]); pass std::ref(bar) as ReadOptions::progress.
  void operator()(double fraction);

  // Draws 100% and ends the line. Without it (e.g. after an error) the destructor only ends the
  // line, leaving the bar where it stood.
  void finish();

 private:
  void draw(int percent);

  std::string label_;
  bool active_;
  bool drawn_ = false;
  int percent_ = -1;
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace polarform::cli
