// SISL's s1961 as the second peer (sisl_peer.h) on a closed contour r = 40 + 5 cos 3θ mm and an
// open one (a quarter meridian r = 50 + 4 cos 2θ, θ in [0, π/2]): the verified curve has the
// degree asked, meets ε by the same dense measurement as polarform's curves and by an independent
// one (the radial error at the polar angle of 20 points per knot span), spans [R.start, R.end],
// closes (closed) or keeps R's end points (open), its eeps is on the ladder, its control points
// lie within a sane bound and grow as ε tightens; the best over degrees 3..8 has no more control
// points than degree 3. Skipped where the build has no SISL.
#include "designers/convert/sisl_peer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "designers/convert/conversion_error.h"
#include "src/error.h"
#include "src/nurbs/knots.h"
#include "tests/support/designers/peer_profiles.h"

namespace polarform {
namespace {

using test::sampled_radial_error;
using test::trefoil;

PolarFunction quarter_meridian() {
  PolarFunction R;
  R.start = 0.0;
  R.end = std::numbers::pi / 2;
  R.derivatives = [](double t, int d, double* out) {
    const double c = std::cos(2 * t), s = std::sin(2 * t);
    const double all[4] = {50 + 4 * c, -8 * s, -16 * c, 32 * s};
    std::copy(all, all + d + 1, out);
  };
  return R;
}

void expect_verified(const PeerCurve& p, const PolarFunction& R, int degree, double tol) {
  ASSERT_TRUE(p.found);
  EXPECT_EQ(p.degree, degree);
  EXPECT_EQ(p.curve.degree(), degree);
  EXPECT_EQ(p.control_points, p.curve.size());
  // Sane: more than a Bézier's, far fewer than the 1441 samples.
  EXPECT_GT(p.control_points, degree);
  EXPECT_LT(p.control_points, 300);
  test::expect_verified_peer(p, R, tol);
}

Eigen::Vector2d on_contour(const PolarFunction& R, double t) {
  return R(t) * Eigen::Vector2d(std::cos(t), std::sin(t));
}

TEST(SislPeer, FitsAClosedContourAsAPeriodicCurve) {
  if constexpr (kSislPeersAvailable) {
    const PolarFunction R = trefoil();
    int previous = 0;
    for (double tol : {1e-2, 1e-3, 1e-4}) {
      SCOPED_TRACE(tol);
      const PeerCurve p = sisl_s1961(R, 3, tol);
      expect_verified(p, R, 3, tol);
      const double a = p.curve.front(), b = p.curve.back(), h = 1e-6;
      EXPECT_LE((p.curve(a) - p.curve(b)).norm(), 1e-9);
      // Periodic: the tangent is continuous across the seam.
      const Eigen::Vector2d left = (p.curve(b) - p.curve(b - h)) / h;
      const Eigen::Vector2d right = (p.curve(a + h) - p.curve(a)) / h;
      EXPECT_LE((left - right).norm(), 1e-3 * right.norm());
      EXPECT_GT(p.control_points, previous);
      previous = p.control_points;
    }
    for (double tol : {1e-2, 1e-3}) {
      SCOPED_TRACE(tol);
      const PeerCurve cubic = sisl_s1961(R, 3, tol);
      const PeerCurve best = sisl_s1961_best(R, 3, 8, tol);
      ASSERT_TRUE(best.found);
      EXPECT_GE(best.degree, 3);
      EXPECT_LE(best.degree, 8);
      expect_verified(best, R, best.degree, tol);
      EXPECT_LE(best.control_points, cubic.control_points);
    }
  } else {
    GTEST_SKIP() << "SISL is not available in this build";
  }
}

TEST(SislPeer, FitsAnOpenMeridianKeepingItsEnds) {
  if constexpr (kSislPeersAvailable) {
    const PolarFunction R = quarter_meridian();
    ASSERT_FALSE(R.closed());
    int previous = 0;
    for (double tol : {1e-2, 1e-3, 1e-4}) {
      SCOPED_TRACE(tol);
      for (int degree : {3, 5}) {
        const PeerCurve p = sisl_s1961(R, degree, tol);
        expect_verified(p, R, degree, tol);
        EXPECT_LE((p.curve(p.curve.front()) - on_contour(R, R.start)).norm(), 1e-9);
        EXPECT_LE((p.curve(p.curve.back()) - on_contour(R, R.end)).norm(), 1e-9);
        if (degree == 3) {
          EXPECT_GE(p.control_points, previous);
          previous = p.control_points;
        }
      }
    }
  } else {
    GTEST_SKIP() << "SISL is not available in this build";
  }
}

TEST(SislPeer, RejectsBadArguments) {
  if constexpr (kSislPeersAvailable) {
    EXPECT_THROW(sisl_s1961(trefoil(), 0, 1e-3), InputError);
    EXPECT_THROW(sisl_s1961(trefoil(), 3, 0.0), InputError);
  } else {
    GTEST_SKIP() << "SISL is not available in this build";
  }
}

}  // namespace
}  // namespace polarform
