// How far a scan resolves the recovered follower motion: for s and each derivative v, a, j the
// signal — the largest |ŝ^(k)| over the revolution — against the noise the scan's σ̂ leaves in
// ŝ^(k) after the displacement fit. The fit is a linear smoother, so that noise is the smoother at
// the fit's own λ applied to pure noise N(0, σ̂²) at the scan's cam angles (Hastie & Tibshirani
// 1990, §3.8); it is estimated by Monte Carlo (fixed seed) as the rms over a 0.5° grid and the
// replicates. A derivative is resolved when its signal is at least kResolvedRatio times its
// noise: the ±3σ band is then within 30 % of the peak, and the curve's shape can be read.
#pragma once

#include <array>

#include "designers/scan/scanned_cam.h"

namespace polarform {

constexpr double kResolvedRatio = 10.0;

struct DerivativeResolution {
  double signal = 0.0;  // max |ŝ^(k)|, mm/rad^k
  double noise = 0.0;   // rms of the propagated noise, mm/rad^k
  bool resolved = false;
};

struct MotionResolution {
  std::array<DerivativeResolution, 4> derivatives;  // s, v, a, j
  int resolved_order = -1;  // highest k with s … s^(k) all resolved (−1: not even s)
  int replicates = 0;
};

// Throws what fit_displacement throws.
MotionResolution resolve_motion(const ScannedCam& scan, int replicates = 4, unsigned seed = 1);

}  // namespace polarform
