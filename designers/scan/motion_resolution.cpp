#include "designers/scan/motion_resolution.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace polarform {

namespace {

constexpr int kGrid = 720;  // 0.5°

// The knot spans of a spline over one revolution [0, 2π].
int spans(const BSplineFunction& f) {
  const Knots& t = f.knots();
  int n = 0;
  for (std::size_t i = 1; i < t.size(); ++i)
    if (t[i] > t[i - 1] && t[i - 1] >= 0.0 && t[i] <= 2 * std::numbers::pi + 1e-12) ++n;
  return n;
}

}  // namespace

MotionResolution resolve_motion(const ScannedCam& scan, int replicates, unsigned seed) {
  MotionResolution out;
  out.replicates = replicates;
  const DisplacementFit& fit = scan.displacement;
  std::array<double, 4> sum_sq{};
  std::mt19937 rng(seed);
  std::normal_distribution<double> N(0.0, fit.noise);
  DisplacementFitOptions o;
  o.degree = fit.height.degree();
  o.spans = spans(fit.height);
  o.lambda = fit.lambda;
  for (int r = 0; r < replicates; ++r) {
    FollowerSamples noise = scan.samples;
    for (Eigen::Index k = 0; k < noise.height.size(); ++k) noise.height[k] = N(rng);
    const DisplacementFit propagated = fit_displacement(noise, o);
    for (int i = 0; i < kGrid; ++i) {
      const Eigen::VectorXd d = propagated.height.derivatives(2 * std::numbers::pi * i / kGrid, 3);
      for (std::size_t k = 0; k < 4; ++k)
        sum_sq[k] += d[static_cast<Eigen::Index>(k)] * d[static_cast<Eigen::Index>(k)];
    }
  }
  for (int i = 0; i < kGrid; ++i) {
    double d[4];
    scan.displacement_derivatives(2 * std::numbers::pi * i / kGrid, 3, d);
    for (std::size_t k = 0; k < 4; ++k)
      out.derivatives[k].signal = std::max(out.derivatives[k].signal, std::abs(d[k]));
  }
  for (std::size_t k = 0; k < 4; ++k) {
    DerivativeResolution& dr = out.derivatives[k];
    dr.noise = std::sqrt(sum_sq[k] / std::max(1, replicates * kGrid));
    dr.resolved = dr.signal >= kResolvedRatio * dr.noise;
    if (dr.resolved && out.resolved_order == static_cast<int>(k) - 1)
      out.resolved_order = static_cast<int>(k);
  }
  return out;
}

}  // namespace polarform
