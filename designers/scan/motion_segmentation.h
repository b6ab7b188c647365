// Segmentation of a recovered follower motion into dwells and motions (rises, returns), the first
// step of recovering a design from a scan. The smoothed displacement ŝ(θ) of the scan
// (displacement_fit.h) is tabulated every 0.1°; a cam angle is still when the range of ŝ over
// ±1° about it is within 2·z·σ_s, σ_s the recovered curve's standard error and z = 3 (a
// Gaussian error leaves a band of ±3σ_s with probability 99.7 %: a dwell is called at that
// confidence). Dwells are runs of still angles at least 2° long; between two dwells the motion is
// split at every reversal larger than the same 2·z·σ_s (a rise running straight into a return);
// a revolution without a dwell is split at its extrema. The boundaries found here are thresholds
// only: law_identification.h refines them by least squares.
#pragma once

#include <vector>

#include "designers/scan/scanned_cam.h"

namespace polarform {

// A dwell, or a zero-length anchor where a motion reverses without a dwell.
struct DwellRun {
  double start = 0.0, end = 0.0;  // rad, start in [0, 2π), end >= start (may pass 2π)
  double level = 0.0;             // mean smoothed height y0 + s over the run, mm
};

// One rise or return between two anchors (the anchors' indices, cyclically), with the
// threshold boundaries and the levels it joins.
struct MotionPiece {
  double start = 0.0, end = 0.0;              // rad, unwrapped: end > start, start in [0, 2π)
  double start_level = 0.0, end_level = 0.0;  // mm
  // The window of samples for its law fit: from the middle of the preceding anchor to the middle
  // of the following one (rad, unwrapped, contains [start, end]).
  double window_start = 0.0, window_end = 0.0;
  std::size_t before = 0, after = 0;  // anchor indices
};

struct MotionSegmentation {
  std::vector<DwellRun> anchors;     // increasing start; dwells and reversal anchors
  std::vector<bool> is_dwell;        // per anchor: a dwell (true) or a reversal point
  std::vector<MotionPiece> motions;  // in the order of their start, each between its anchors
  double still_band = 0.0;           // 2·z·σ_s, mm: the range a dwell's ŝ stays within
  double confidence = 0.0;           // the two-sided Gaussian probability of the ±z band
};

// Throws InputError when the motion has no rise (a circle about its centre: nothing to segment).
MotionSegmentation segment_motion(const ScannedCam& scan);

}  // namespace polarform
