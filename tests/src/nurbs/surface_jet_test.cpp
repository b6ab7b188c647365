// surface_jet against NurbsSurface::derivatives (NURBS Book A4.4) on random rational surfaces,
// including degree 1 directions and parameters on knots.
#include <gtest/gtest.h>

#include <random>

#include "src/nurbs/surface_jet.h"

namespace polarform {
namespace {

TEST(SurfaceJet, MatchesGeneralDerivatives) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> coord(-2, 2), weight(0.3, 3), unit(0, 1);
  for (int pu = 1; pu <= 4; ++pu)
    for (int pv = 1; pv <= 4; ++pv) {
      const int nu = pu + 3, nv = pv + 2;
      NurbsSurface::Points points;
      std::vector<double> weights;
      for (int k = 0; k < nu * nv; ++k) {
        points.emplace_back(coord(rng), coord(rng), coord(rng));
        weights.push_back(weight(rng));
      }
      const NurbsSurface s(pu, pv, uniform_clamped_knots(pu, 3, 0, 1),
                           uniform_clamped_knots(pv, 2, -1, 2), points, weights);
      for (int k = 0; k < 200; ++k) {
        // Every fourth parameter lies on a knot.
        const double u = k % 4 == 0 ? (k / 4 % 4) / 3.0 : unit(rng);
        const double v = k % 4 == 0 ? -1.0 + 1.5 * (k / 4 % 3) : -1.0 + 3.0 * unit(rng);
        const SurfaceJet j = surface_jet(s, u, v);
        const NurbsSurface::Points d = s.derivatives(u, v, 2);
        const double tol = 1e-12 * (1.0 + d[6].norm() + d[2].norm() + d[4].norm());
        EXPECT_NEAR((j.s - d[0]).norm(), 0.0, tol);
        EXPECT_NEAR((j.sv - d[1]).norm(), 0.0, tol);
        EXPECT_NEAR((j.svv - d[2]).norm(), 0.0, tol);
        EXPECT_NEAR((j.su - d[3]).norm(), 0.0, tol);
        EXPECT_NEAR((j.suv - d[4]).norm(), 0.0, tol);
        EXPECT_NEAR((j.suu - d[6]).norm(), 0.0, tol);
      }
    }
}

}  // namespace
}  // namespace polarform
