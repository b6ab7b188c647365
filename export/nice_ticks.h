// "Nice" axis ticks and their labels: linear steps from the 1-2-5 sequence (or a given step),
// decades on log axes with 2..9 minor ticks, and 1-2-5 mantissas for log ranges under two
// decades. Labels use uniform decimals, a true minus sign and a common ×10ⁿ factor for very large
// or small values. Which candidate fits an axis's pixel length is decided in export/plot_axis.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace polarform {

struct Tick {
  double value;
  std::string label;
};

struct TickSet {
  std::vector<Tick> major;    // labelled, ascending
  std::vector<double> minor;  // unlabelled, ascending
  std::string factor;         // "×10⁶" when labels show value / 10⁶; empty otherwise
};

// The 1-2-5 sequence indexed by integers: nice_step(0) = 1, (1) = 2, (2) = 5, (3) = 10, (-1) = 0.5.
double nice_step(int index);

// Index of the smallest nice step >= raw (raw > 0).
int nice_step_index(double raw);

// Ticks at the multiples of step (> 0) inside [lo, hi]; the caller keeps (hi - lo) / step modest.
TickSet linear_ticks(double lo, double hi, double step);

// Ticks at the decades 10^k inside [lo, hi] (0 < lo < hi) whose exponent is a multiple of stride.
// Minor ticks: 2..9 × 10^k with stride 1, the skipped decades otherwise. Labels are plain
// decimals if all labelled exponents are in -3..4 ("0.001", "100"), else powers ("10⁻⁶").
TickSet log_decade_ticks(double lo, double hi, int stride);

// Ticks at m × 10^k inside [lo, hi] for the given mantissas (e.g. {1, 2, 5}); the remaining
// mantissas of 1..9 become minor ticks. For log ranges too narrow for two decades.
TickSet log_mantissa_ticks(double lo, double hi, std::span<const int> mantissas);

// 10^k exactly as the decimal literal "1ek" reads.
double power_of_ten(int k);

// "10" followed by k in superscript digits: "10⁻³".
std::string superscript_power_of_ten(int k);

}  // namespace polarform
