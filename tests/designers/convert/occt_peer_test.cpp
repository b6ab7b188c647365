// Open CASCADE as the peer (occt_peer.h) on a closed contour r = 40 + 5 cos 3θ mm: the verified
// curve meets ε by the same dense measurement as polarform's curves and by an independent one
// (the radial error at the polar angle of 20 points per knot span), its pole count is the
// curve's, its Tol3D is on the ladder, its ends meet, and a tighter ε needs more poles. Skipped
// where the build has no Open CASCADE.
#include "designers/convert/occt_peer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "designers/convert/conversion_error.h"
#include "src/nurbs/knots.h"
#include "tests/support/designers/peer_profiles.h"

namespace polarform {
namespace {

using test::sampled_radial_error;
using test::trefoil;

TEST(OcctPeer, FitsAClosedContourWithinTheTolerance) {
  if constexpr (kOcctPeersAvailable) {
    const PolarFunction R = trefoil();
    int previous = 0;
    for (double tol : {1e-2, 1e-3}) {
      SCOPED_TRACE(tol);
      for (int deg_max : {3, 8}) {
        const PeerCurve p = occt_points_to_bspline(R, 3, deg_max, tol);
        ASSERT_TRUE(p.found);
        EXPECT_EQ(p.control_points, p.curve.size());
        EXPECT_EQ(p.degree, p.curve.degree());
        EXPECT_GE(p.degree, 3);
        EXPECT_LE(p.degree, deg_max);
        test::expect_verified_peer(p, R, tol);
        EXPECT_LE((p.curve(p.curve.front()) - p.curve(p.curve.back())).norm(), tol);
        if (deg_max == 3) {
          EXPECT_GT(p.control_points, previous);
          previous = p.control_points;
        }
      }
    }
  } else {
    GTEST_SKIP() << "Open CASCADE is not available in this build";
  }
}

}  // namespace
}  // namespace polarform
