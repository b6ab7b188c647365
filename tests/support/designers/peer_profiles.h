// What the peer converters' tests share: a smooth closed test profile, the tests' own radial
// error of a peer's curve, sampled on every knot span independently of the peers' measurement,
// and the checks every verified peer curve passes.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "designers/convert/conversion_error.h"
#include "designers/convert/peer_fit.h"
#include "designers/convert/polar_function.h"
#include "src/nurbs/knots.h"
#include "src/nurbs/nurbs_curve.h"

namespace polarform::test {

// r = 40 + 5 cos 3ψ over a full turn.
inline PolarFunction trefoil() {
  PolarFunction R;
  R.start = 0.0;
  R.end = 2 * std::numbers::pi;
  R.derivatives = [](double t, int d, double* out) {
    const double c = std::cos(3 * t), s = std::sin(3 * t);
    const double all[4] = {40 + 5 * c, -15 * s, -45 * c, 135 * s};
    std::copy(all, all + d + 1, out);
  };
  return R;
}

// Max |ρ − R(ψ)| over 20 points per knot span, ψ the point's own polar angle.
inline double sampled_radial_error(const NurbsCurve2d& c, const PolarFunction& R) {
  const std::vector<Breakpoint> b = breakpoints(c.knots());
  double worst = 0.0;
  for (std::size_t j = 0; j + 1 < b.size(); ++j)
    for (int k = 0; k <= 20; ++k) {
      const Eigen::Vector2d p = c(b[j].value + (b[j + 1].value - b[j].value) * k / 20);
      worst = std::max(worst, std::abs(p.norm() - R(std::atan2(p.y(), p.x()))));
    }
  return worst;
}

// A peer curve verified at tol: its error measured, within tol, no less than the converter's
// default measurement finds (both refined by Brent's search, which stops within 1e-7 of each
// bracket: values within 1e-9), within tol by the tests' own sampling, found at a tolerance of the
// ladder, on R's domain.
inline void expect_verified_peer(const PeerCurve& p, const PolarFunction& R, double tol) {
  EXPECT_GT(p.max_radial_error, 0.0);
  EXPECT_LE(p.max_radial_error, tol);
  EXPECT_GE(p.max_radial_error,
            profile_error(p.curve, R, p.curve.front(), p.curve.back()).max_radial * (1 - 1e-9));
  EXPECT_LE(sampled_radial_error(p.curve, R), tol);
  EXPECT_TRUE(std::any_of(std::begin(kPeerToleranceLadder), std::end(kPeerToleranceLadder),
                          [&](double f) { return p.peer_tolerance == f * tol; }))
      << p.peer_tolerance;
  EXPECT_NEAR(p.curve.front(), R.start, 1e-12);
  EXPECT_NEAR(p.curve.back(), R.end, 1e-12);
}

}  // namespace polarform::test
