#include "designers/scan/phase_alignment.h"

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "src/error.h"

namespace polarform {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// The grid shift m (δ = m·2π/n) minimising Σ_i (r_i − q_{i−m})², and that sum.
std::pair<int, double> best_shift(const std::vector<double>& r, const std::vector<double>& q) {
  const int n = static_cast<int>(r.size());
  int best = 0;
  double best_sum = INFINITY;
  for (int m = 0; m < n; ++m) {
    double sum = 0.0;
    for (int i = 0; i < n; ++i) sum += std::pow(r[i] - q[(i - m + n) % n], 2);
    if (sum < best_sum) best_sum = sum, best = m;
  }
  return {best, best_sum};
}

}  // namespace

PhaseAlignment align_phase(const std::function<double(double)>& scan,
                           const std::function<double(double)>& nominal, bool allow_mirror,
                           int samples) {
  if (samples < 16)
    throw InputError("phase alignment: " + std::to_string(samples) +
                     " samples, expected at least 16");
  const auto n = static_cast<std::size_t>(samples);
  const double h = kTwoPi / samples;
  std::vector<double> psi(n), direct(n), mirror(n), q(n);
  for (std::size_t i = 0; i < n; ++i) {
    psi[i] = h * static_cast<double>(i);
    direct[i] = scan(psi[i]);
    mirror[i] = scan(-psi[i]);
    q[i] = nominal(psi[i]);
  }
  PhaseAlignment out;
  auto [best, sum] = best_shift(direct, q);
  if (allow_mirror) {
    const auto [m, m_sum] = best_shift(mirror, q);
    if (m_sum < sum) best = m, out.mirrored = true;
  }
  const std::vector<double>& r = out.mirrored ? mirror : direct;
  const auto rms = [&](double delta) {
    double s = 0.0;
    for (std::size_t i = 0; i < n; ++i) s += std::pow(r[i] - nominal(psi[i] - delta), 2);
    return std::sqrt(s / static_cast<double>(n));
  };
  // Golden section on [δ_best − h, δ_best + h]: the minimum of a smooth rms lies in this bracket.
  const double g = (std::sqrt(5.0) - 1) / 2;
  double a = (best - 1) * h, b = (best + 1) * h;
  double c = b - g * (b - a), d = a + g * (b - a), fc = rms(c), fd = rms(d);
  while (b - a > 1e-9) {
    if (fc < fd) {
      b = d, d = c, fd = fc;
      c = b - g * (b - a), fc = rms(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + g * (b - a), fd = rms(d);
    }
  }
  out.phase = std::fmod(0.5 * (a + b) + kTwoPi, kTwoPi);
  out.rms = rms(out.phase);
  return out;
}

}  // namespace polarform
