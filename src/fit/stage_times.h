// Wall-clock seconds spent in each stage of a fit, and the clock that measures them. The fitters
// fill the stages they run (reading only when they read a file); `total` is the whole call.
#pragma once

#include <chrono>

namespace polarform {

struct StageTimes {
  double read = 0.0;      // point-cloud file
  double frame = 0.0;     // local frame: quadric fit, classification, transform (4.5)
  double sync = 0.0;      // orthogonal-coordinate transform and parameter synchronization
  double check = 0.0;     // single-valuedness check
  double knots = 0.0;     // knot placement (and refinement bookkeeping)
  double assembly = 0.0;  // sparse normal equations
  double solve = 0.0;     // factorisation, fairness weight choice
  double product = 0.0;   // symbolic product, clipping, caps, back-transform (4.6)
  double error = 0.0;     // true point-to-geometry distances and their statistics
  double total = 0.0;
};

// Seconds since construction or the last lap().
class StageClock {
 public:
  StageClock() : last_(std::chrono::steady_clock::now()) {}
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }

 private:
  std::chrono::steady_clock::time_point last_;
};

}  // namespace polarform
