// The control net of F chosen by the data: nets grown one direction at a time, each fitted by
// least squares to the samples and scored by generalized cross-validation GCV = (RSS/n)/(1 − m/n)²
// (Craven & Wahba 1979); the growth stops when GCV no longer improves (the residual has reached
// the noise level), and never exceeds one coefficient per kSamplesPerCoefficient samples. The
// noise estimate is σ̂ = sqrt(RSS/(n − m)) of the chosen net.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "src/fit/function_fit.h"

namespace polarform {

// The rule "never more coefficients than the data can determine": m <= n / 4.
constexpr int kSamplesPerCoefficient = 4;
// Larger clouds choose their net on an evenly strided subsample of this many samples.
constexpr std::size_t kSelectionSamples = 100000;
// A candidate must lower GCV by this fraction to count as an improvement.
constexpr double kGcvImprovement = 0.01;

struct NetCandidate {
  int size_u = 0, size_v = 0;
  long coefficients = 0;  // free coefficients (pole rows tied)
  double rms = 0.0;       // parametric residual |F(u_k, v_k) − g_k|
  double gcv = 0.0;
};

struct NetSelection {
  bool automatic = false;      // chosen here (else given or refined to a tolerance)
  std::size_t samples = 0;     // samples the choice used
  long max_coefficients = 0;   // samples / kSamplesPerCoefficient
  int size_u = 0, size_v = 0;  // the chosen net
  double noise = 0.0;          // σ̂ at the chosen net, mm (along the rays)
  // GCV stopped improving: σ̂ is the noise level. Otherwise the growth hit the coefficient rule or
  // the size limits and σ̂ is only an upper bound of the noise (model error included).
  bool noise_reached = false;
  std::vector<NetCandidate> candidates;  // in the order tried
  std::string stop;                      // why the growth stopped
};

// Every k-th sample so that at most `count` remain (all of them when there are fewer).
Samples strided_subsample(const Samples& samples, std::size_t count);

// The least-squares fit of F with a fixed (size_u, size_v) net, scored.
NetCandidate evaluate_net(const Samples& samples, const FunctionSpace& space,
                          const FunctionFitOptions& options, int size_u, int size_v);

// Grows the directions whose size options leaves 0 (and whose max_size exceeds 1) from
// max(degree + 1, 4), by half again as many spans per step (a multiple of the base arcs), in u,
// in v or in both, whichever lowers GCV most; the others stay at their given size. Stops after two
// candidates without a kGcvImprovement gain, or at the coefficient rule or the size limits, and
// returns the best net seen.
NetSelection select_net(const Samples& samples, const FunctionSpace& space,
                        const FunctionFitOptions& options);

}  // namespace polarform
