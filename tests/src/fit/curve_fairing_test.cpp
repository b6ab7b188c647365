// Local fairing (MIT 13.472J §8.2.3; spec M2–M4): the p-th derivative jumps against a closed form,
// Farin's least-squares knot removal and re-insertion (the jump gone, the measured deviation within
// its bound, exactly local) and Kjellander's data fairing, on the bumped semicircle of the spec.
#include "src/fit/curve_fairing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "src/error.h"
#include "src/nurbs/curve_interpolation.h"
#include "src/nurbs/curve_interrogation.h"
#include "src/nurbs/knot_insertion.h"
#include "src/nurbs/knot_removal.h"
#include "src/nurbs/knots.h"

namespace polarform {
namespace {

// 19 points on a semicircle of radius 10 at 10° steps, point 9 pushed out radially by 0.1, with
// chord-length parameters (spec M3/M4 test case).
struct Bumped {
  Eigen::MatrixXd points;
  Eigen::VectorXd t;
};
Bumped bumped_semicircle() {
  Bumped b{Eigen::MatrixXd(2, 19), Eigen::VectorXd(19)};
  for (int k = 0; k < 19; ++k) {
    const double a = k * std::numbers::pi / 18, r = k == 9 ? 10.1 : 10.0;
    b.points.col(k) = Eigen::Vector2d(r * std::cos(a), r * std::sin(a));
  }
  b.t[0] = 0;
  for (int k = 1; k < 19; ++k) b.t[k] = b.t[k - 1] + (b.points.col(k) - b.points.col(k - 1)).norm();
  return b;
}

double jump_at(const BSpline& c, double u) {
  for (const SplineKnotJump& j : top_derivative_jumps(c))
    if (j.u == u) return j.jump;
  return -1;
}

// max over 20 001 samples of |a(u) − b(u)|.
double sampled_deviation(const BSpline& a, const BSpline& b) {
  double d = 0.0;
  for (int k = 0; k <= 20000; ++k) {
    const double u = a.front() + (a.back() - a.front()) * k / 20000;
    d = std::max(d, (a.point(u) - b.point(u)).norm());
  }
  return d;
}

TEST(DerivativeJumps, CubicBasisFunctionClosedForm) {
  const double h = 0.7;
  Knots U(4, 0.0);
  for (int k = 1; k < 10; ++k) U.push_back(k * h);
  U.insert(U.end(), 4, 10 * h);
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(1, static_cast<Eigen::Index>(U.size()) - 4);
  c(0, 6) = 1.0;  // N_6 on knots u_6..u_10 = 3h..7h, all interior
  const std::vector<SplineKnotJump> jumps = top_derivative_jumps(BSpline(3, U, c));
  const double expected[5] = {1, 4, 6, 4, 1};
  for (int k = 0; k < 5; ++k)
    EXPECT_NEAR(jump_at(BSpline(3, U, c), (3 + k) * h) * h * h * h, expected[k],
                1e-12 * expected[k])
        << k;
  for (const SplineKnotJump& j : jumps)
    if (j.u < 3 * h - 1e-12 || j.u > 7 * h + 1e-12) {
      EXPECT_EQ(j.jump, 0.0) << j.u;
    }
}

TEST(FarinFairing, OneStepRemovesTheJumpWithinItsBoundAndIsLocal) {
  const Bumped b = bumped_semicircle();
  const BSpline R = interpolate_cubic(b.points, b.t);
  const double u = b.t[9];
  const double before = jump_at(R, u);
  const LeastSquaresRemoval removal = remove_knot_least_squares(R, u);
  const BSpline F = insert_knot(removal.spline, u, 1);
  EXPECT_LE(jump_at(F, u), 1e-9 * before);
  EXPECT_LE(sampled_deviation(R, F), removal.bound * (1 + 1e-12));
  // Knot u = t_9 is U[r] with r = 3 + 9: only P_{r−3}..P_{r−1} move, the others bit for bit.
  const int r = 12;
  for (int i = 0; i < R.size(); ++i)
    if (i < r - 3 || i > r - 1) {
      EXPECT_EQ(R.coefs().col(i), F.coefs().col(i)) << i;
    }
  for (int k = 1; k < 18; ++k)
    if (std::abs(k - 9) > 3) {
      EXPECT_NEAR(jump_at(F, b.t[k]), jump_at(R, b.t[k]), 1e-12 * before) << k;
    }
  // The bump: R(t_9) was 0.1 off the circle; faired, less than half of it is left.
  EXPECT_LT(std::abs(F.point(u).norm() - 10.0), 0.05);
}

TEST(FarinFairing, TheLoopNeverMovesTheCurveBeyondTheTolerance) {
  const Bumped b = bumped_semicircle();
  const BSpline R = interpolate_cubic(b.points, b.t);
  for (const double eps : {0.02, 0.05, 0.2}) {
    FairingOptions o;
    o.tolerance = eps;
    const CurveFairing f = farin_fair(R, o);
    EXPECT_FALSE(f.steps.empty()) << eps;
    EXPECT_LE(f.total_bound, eps);
    EXPECT_LE(sampled_deviation(R, f.spline), f.total_bound * (1 + 1e-12)) << eps;
  }
}

TEST(FarinFairing, SurfaceRowsAndColumnsFlattenABump) {
  Knots U = uniform_clamped_knots(3, 5, 0, 1);
  Eigen::MatrixXd net = Eigen::MatrixXd::Zero(3, 8 * 8);
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) net.col(i * 8 + j) << i, j, (i == 4 && j == 3) ? 1.0 : 0.0;
  const BSplineSurface s(3, 3, U, U, net);
  const auto max_z = [](const BSplineSurface& x) {
    double z = 0;
    for (int a = 0; a <= 100; ++a)
      for (int c = 0; c <= 100; ++c) z = std::max(z, std::abs(x.point(a / 100.0, c / 100.0)(2)));
    return z;
  };
  FairingOptions o;
  o.tolerance = 3.0;  // of summed per-point bounds, an overestimate of the surface's move
  const SurfaceFairing fu = farin_fair_surface_u(s, o);
  const SurfaceFairing fv = farin_fair_surface_v(fu.surface, o);
  EXPECT_LE(max_z(fv.surface), 0.5 * max_z(s)) << max_z(s);
  double moved = 0;
  for (int a = 0; a <= 100; ++a)
    for (int c = 0; c <= 100; ++c)
      moved = std::max(
          moved, (fv.surface.point(a / 100.0, c / 100.0) - s.point(a / 100.0, c / 100.0)).norm());
  EXPECT_LE(moved, fu.total_bound + fv.total_bound);
}

TEST(KjellanderFairing, RestoresTheBumpedPointAndLeavesTheOthers) {
  const Bumped b = bumped_semicircle();
  const BSpline R = interpolate_cubic(b.points, b.t);
  FairingOptions one;
  one.tolerance = 1.0;
  one.max_passes = 1;
  const KjellanderFairing f = kjellander_fair(b.points, b.t, one);
  ASSERT_EQ(f.steps.size(), 1u);
  EXPECT_EQ(f.steps[0].u, b.t[9]);  // the worst jump is at the disturbed point
  for (int k = 0; k < 19; ++k)
    if (k != 9) {
      EXPECT_LT((f.spline.point(b.t[k]) - b.points.col(k)).norm(), 1e-13 * 10) << k;
    }
  const double bump_after = std::abs(f.values.col(9).norm() - 10.0);
  EXPECT_LE(bump_after, 0.5 * 0.1);
  EXPECT_LE(f.steps[0].jump_after, 0.5 * f.steps[0].jump_before);
  EXPECT_GT(jump_at(R, b.t[9]), 0.0);
  // With ε = 0.05 the loop never moves a point by more than 0.05 from where it was measured.
  FairingOptions eps;
  eps.tolerance = 0.05;
  const KjellanderFairing g = kjellander_fair(b.points, b.t, eps);
  EXPECT_LE(g.max_data_move, 0.05);
  EXPECT_LE((g.values - b.points).colwise().norm().maxCoeff(), 0.05);
}

// The check: the cubic through a semicircle's 19 points with one pushed out by 0.5 (5 % of
// the radius) has inflections around it; Kjellander's fairing within 1 mm restores the point to
// within that tolerance and the curvature plot to the semicircle's true count, none.
TEST(KjellanderFairing, RestoresTheTrueNumberOfInflections) {
  Bumped b = bumped_semicircle();
  b.points.col(9) *= 10.5 / 10.1;
  const auto count = [](const BSpline& c) {
    Eigen::MatrixXd h(3, c.size());
    h.topRows(2) = c.coefs();
    h.row(2).setOnes();
    return inflections(NurbsCurve2d(BSpline(c.degree(), c.knots(), h))).size();
  };
  EXPECT_GE(count(interpolate_cubic(b.points, b.t)), 2u);
  FairingOptions o;
  o.tolerance = 1.0;
  const KjellanderFairing f = kjellander_fair(b.points, b.t, o);
  EXPECT_EQ(count(f.spline), 0u);
  EXPECT_LE(f.max_data_move, 1.0);
  EXPECT_LT(std::abs(f.values.col(9).norm() - 10.0), 0.05);
}

TEST(Fairing, RefusesANonPositiveTolerance) {
  const Bumped b = bumped_semicircle();
  EXPECT_THROW(farin_fair(interpolate_cubic(b.points, b.t), FairingOptions{}), InputError);
  EXPECT_THROW(kjellander_fair(b.points, b.t, FairingOptions{}), InputError);
}

}  // namespace
}  // namespace polarform
