// Closed forms the cam-job tests check against, written out independently of designers/cam: the
// displacement of examples/cams/roller.xml (cycloidal rise, 4-5-6-7 return) with its θ-derivatives,
// and the radius of curvature of a polar curve (DESIGN.md §4.4).
#pragma once

#include <cmath>
#include <numbers>

#include "src/units.h"

namespace polarform::cam_job_test {

constexpr double kPi = std::numbers::pi;

// s, ds/dθ, d²s/dθ² of roller.xml (mm, per rad) at cam angle θ in degrees, [0, 360): dwell to 90°,
// cycloidal rise of 20 mm to 180°, dwell to 240°, 4-5-6-7 return to 360°.
struct Motion {
  double s = 0, v = 0, a = 0;
};

inline Motion roller_motion(double theta_deg) {
  const double h = 20;
  if (theta_deg < 90) return {};
  if (theta_deg < 180) {
    const double beta = kPi / 2, x = (theta_deg - 90) / 90, w = 2 * kPi * x;
    return {h * (x - std::sin(w) / (2 * kPi)), h / beta * (1 - std::cos(w)),
            2 * kPi * h / (beta * beta) * std::sin(w)};
  }
  if (theta_deg < 240) return {h, 0, 0};
  const double beta = 2 * kPi / 3, x = (theta_deg - 240) / 120;
  const double x2 = x * x, x3 = x2 * x, x4 = x3 * x;
  const double p = 35 * x4 - 84 * x4 * x + 70 * x4 * x2 - 20 * x4 * x3;  // Norton: 4-5-6-7
  const double dp = 140 * x3 - 420 * x4 + 420 * x4 * x - 140 * x4 * x2;
  const double ddp = 420 * x2 - 1680 * x3 + 2100 * x4 - 840 * x4 * x;
  return {h * (1 - p), -h / beta * dp, -h / (beta * beta) * ddp};
}

// Signed radius of curvature of the polar curve r(θ): (r² + r'²)^{3/2} / (r² + 2r'² − r r'').
inline double polar_radius_of_curvature(double r, double dr, double ddr) {
  return std::pow(r * r + dr * dr, 1.5) / (r * r + 2 * dr * dr - r * ddr);
}

}  // namespace polarform::cam_job_test
