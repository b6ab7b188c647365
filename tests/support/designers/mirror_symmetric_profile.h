// A profile that is its own mirror image, as a vessel head's meridian is: r = 50 + 5 cos 2ψ +
// cos 4ψ on [0, π], symmetric about the line ψ = π/2 (the y axis); and the checks a curve fitted
// to it as its own mirror image passes.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "designers/convert/polar_function.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform::test {

// With π/2 a breakpoint (as a head's apex is) when `apex_breakpoint`, so that the converter sees
// the mirror (mirror_symmetric, polar_function.h); without it, a plain smooth open profile.
inline PolarFunction mirror_symmetric_profile(bool apex_breakpoint = true) {
  PolarFunction R;
  R.start = 0.0;
  R.end = std::numbers::pi;
  if (apex_breakpoint) R.breakpoints = {std::numbers::pi / 2};
  R.derivatives = [](double t, int d, double* out) {
    const double c2 = std::cos(2 * t), s2 = std::sin(2 * t), c4 = std::cos(4 * t),
                 s4 = std::sin(4 * t);
    const double all[4] = {50 + 5 * c2 + c4, -10 * s2 - 4 * s4, -20 * c2 - 16 * c4,
                           40 * s2 + 64 * s4};
    for (int k = 0; k <= d; ++k) out[k] = all[k];
  };
  return R;
}

// C(a + b − u) is C(u) mirrored in the y axis, on knots symmetric about the middle m = (a + b)/2;
// C(m) lies on the axis, level, and C is C^(p−1) across it at least: one curve whose control
// values are mirror pairs, m a simple knot or none.
inline void expect_own_mirror_image(const NurbsCurve2d& C) {
  const double a = C.front(), b = C.back(), m = 0.5 * (a + b);
  for (int k = 0; k <= 200; ++k) {
    const double u = a + (b - a) * k / 200;
    const Eigen::Vector2d p = C(u), q = C(a + b - u);
    EXPECT_NEAR(p.x(), -q.x(), 1e-9);
    EXPECT_NEAR(p.y(), q.y(), 1e-9);
  }
  for (std::size_t i = 0; i < C.knots().size(); ++i)
    EXPECT_NEAR(C.knots()[i] - a, b - C.knots()[C.knots().size() - 1 - i], 1e-12);
  const auto d = C.derivatives(m, 1);
  EXPECT_NEAR(d[0].x(), 0.0, 1e-12);
  EXPECT_NEAR(d[1].y(), 0.0, 1e-9 * d[1].norm());
  EXPECT_LE(std::count(C.knots().begin(), C.knots().end(), m), 1);
}

}  // namespace polarform::test
