// Parametric LSQ surface fit (spec B2): exact recovery of a known net with and without a fixed
// boundary, correction rounds on distorted parameters, tolerance-driven refinement.
#include "src/fit/surface_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "src/error.h"
#include "src/nurbs/point_inversion.h"
#include "tests/src/fit/fit_test_support.h"
#include "tests/src/fit/patch_test_support.h"

namespace polarform {
namespace {

double net_difference(const NurbsSurface& a, const NurbsSurface& b) {
  double d = 0.0;
  for (int i = 0; i < a.size_u(); ++i)
    for (int j = 0; j < a.size_v(); ++j)
      d = std::max(d, (a.control_point(i, j) - b.control_point(i, j)).norm());
  return d;
}

// B2.1: a random bicubic 8×8 net sampled at known parameters comes back to 1e-11·size.
TEST(SurfaceFit, RecoversKnownNetWithAndWithoutBoundary) {
  const double size = 50.0;
  const NurbsSurface truth = test::random_bicubic(8, size, 7);
  const test::Samples s = test::sample_surface(truth, 3000, 8);
  SurfaceFitOptions o;
  o.control_u = o.control_v = 8;
  const SurfaceFit free_fit = fit_surface(s.points, s.u, s.v, o);
  ASSERT_EQ(free_fit.surface.size_u(), 8);
  const double free_error = net_difference(free_fit.surface, truth);
  EXPECT_LE(free_error, 1e-11 * size);
  EXPECT_LE(free_fit.max_distance, 1e-11 * size);

  SurfaceFitOptions ob;
  ob.boundary = test::exact_boundary(truth);
  const SurfaceFit fixed_fit = fit_surface(s.points, s.u, s.v, ob);
  ASSERT_EQ(fixed_fit.surface.size_u(), 8);
  ASSERT_EQ(fixed_fit.surface.size_v(), 8);
  const double fixed_error = net_difference(fixed_fit.surface, truth);
  EXPECT_LE(fixed_error, 1e-11 * size);
  RecordProperty("net_error_free", test::sci(free_error));
  RecordProperty("net_error_fixed", test::sci(fixed_error));
}

// A boundary of lower degree is elevated, and more control points than the boundary's are
// reached by uniform insertion: the boundary rows stay on the curves.
TEST(SurfaceFit, FixedBoundaryIsElevatedAndRefined) {
  const NurbsSurface truth = test::random_bicubic(4, 10.0, 3);
  const test::Samples s = test::sample_surface(truth, 2000, 4);
  SurfaceFitOptions o;
  o.boundary = test::exact_boundary(truth);
  o.degree_u = o.degree_v = 4;
  o.control_u = 9;
  o.control_v = 7;
  const SurfaceFit f = fit_surface(s.points, s.u, s.v, o);
  EXPECT_EQ(f.surface.size_u(), 9);
  EXPECT_EQ(f.surface.size_v(), 7);
  for (double t : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    EXPECT_LE((f.surface.point(t, 0.0) - truth.point(t, 0.0)).norm(), 1e-12 * 10);
    EXPECT_LE((f.surface.point(1.0, t) - truth.point(1.0, t)).norm(), 1e-12 * 10);
  }
  EXPECT_LE(f.max_distance, 1e-10);
}

// B2.2: S8(a) with the parameters of its bilinear Coons base (global projection onto it); the
// correction rounds decrease the max distance and at least halve it within 10 rounds; the kept
// round is never worse than round 0.
TEST(SurfaceFit, CorrectionRoundsImproveCoonsParameters) {
  const NurbsSurface truth = test::bulged_quarter();
  test::Samples s = test::sample_surface(truth, 11517, 12);
  const SurfaceProjector coons(test::bilinear_coons_of(truth));
  for (Eigen::Index k = 0; k < s.u.size(); ++k) {
    const SurfaceProjection f = coons.project(s.points.col(k));
    s.u[k] = f.u;
    s.v[k] = f.v;
  }
  SurfaceFitOptions o;
  o.boundary = test::exact_boundary(truth);
  o.correction_rounds = 10;
  const SurfaceFit f = fit_surface(s.points, s.u, s.v, o);
  ASSERT_EQ(f.rounds.size(), 11u);
  for (int r = 1; r <= f.best_round; ++r)
    EXPECT_LE(f.rounds[r].max_distance, f.rounds[r - 1].max_distance) << "round " << r;
  EXPECT_LE(f.max_distance, 0.5 * f.rounds[0].max_distance);
  EXPECT_LE(f.max_distance, f.rounds[0].max_distance);
  EXPECT_DOUBLE_EQ(f.max_distance, f.rounds[f.best_round].max_distance);
  RecordProperty("round0_max", test::sci(f.rounds[0].max_distance));
  RecordProperty("best_max", test::sci(f.max_distance));
  RecordProperty("best_round", f.best_round);
}

// The kept round is the best even when later rounds get worse: one round on exact parameters
// cannot improve (the first fit is exact), so the round-0 surface is returned.
TEST(SurfaceFit, NeverReturnsWorseThanRoundZero) {
  const NurbsSurface truth = test::random_bicubic(6, 10.0, 31);
  const test::Samples s = test::sample_surface(truth, 2000, 32);
  SurfaceFitOptions o;
  o.control_u = o.control_v = 6;
  o.correction_rounds = 3;
  const SurfaceFit f = fit_surface(s.points, s.u, s.v, o);
  EXPECT_LE(f.max_distance, f.rounds[0].max_distance);
  EXPECT_LE(f.max_distance, 1e-10);
  // An over-relaxed round (ω = 2) and a plain one, neither gaining 1 %: stop.
  EXPECT_LE(f.rounds.size(), 3u);
}

// Tolerance mode: a surface that needs more than a 4×4 net gets knots until it meets the tolerance.
TEST(SurfaceFit, ToleranceModeRefinesUntilMet) {
  const double size = 30.0;
  const NurbsSurface truth = test::random_bicubic(9, size, 21);
  const test::Samples s = test::sample_surface(truth, 8000, 22);
  SurfaceFitOptions o;
  o.tolerance = 3e-3 * size;
  const SurfaceFit f = fit_surface(s.points, s.u, s.v, o);
  EXPECT_TRUE(f.tolerance_met);
  EXPECT_LE(f.max_distance, o.tolerance);
  EXPECT_GT(f.surface.size_u() * f.surface.size_v(), 16);
  SurfaceFitOptions four;
  four.control_u = four.control_v = 4;
  EXPECT_GT(fit_surface(s.points, s.u, s.v, four).max_distance, o.tolerance);
  RecordProperty("net",
                 std::to_string(f.surface.size_u()) + "x" + std::to_string(f.surface.size_v()));
  RecordProperty("max", test::sci(f.max_distance));
}

// Smoothing keeps a net with more control points than the data can fix well posed.
TEST(SurfaceFit, SmoothingMakesUnderdeterminedNetSolvable) {
  const NurbsSurface truth = test::random_bicubic(4, 10.0, 5);
  const test::Samples s = test::sample_surface(truth, 30, 6);
  SurfaceFitOptions o;
  o.control_u = o.control_v = 10;
  EXPECT_THROW(fit_surface(s.points, s.u, s.v, o), InputError);
  o.smoothing = 1e-6;
  const SurfaceFit f = fit_surface(s.points, s.u, s.v, o);
  EXPECT_LE(f.max_distance, 0.05);
}

// The thin-plate energy vanishes on an affine map c + u·e + v·f: any smoothing weight keeps it.
TEST(SurfaceFit, SmoothingKeepsAnAffinePatch) {
  const int n = 500;
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Eigen::Matrix3Xd p(3, n);
  Eigen::VectorXd u(n), v(n);
  for (int k = 0; k < n; ++k) {
    u[k] = U(rng);
    v[k] = U(rng);
    p.col(k) = Eigen::Vector3d(1, 2, 3) + u[k] * Eigen::Vector3d(10, 1, 2) +
               v[k] * Eigen::Vector3d(-1, 8, 3);
  }
  SurfaceFitOptions o;
  o.control_u = 7;
  o.control_v = 5;
  o.smoothing = 1e3;
  EXPECT_LE(fit_surface(p, u, v, o).max_distance, 1e-10);
  for (int k = 0; k < n; ++k) p(2, k) += 3 * u[k] * u[k];  // curved: now smoothing flattens it
  EXPECT_GT(fit_surface(p, u, v, o).max_distance, 1e-2);
}

TEST(SurfaceFit, RejectsBadInput) {
  const NurbsSurface truth = test::random_bicubic(4, 10.0, 5);
  test::Samples s = test::sample_surface(truth, 100, 6);
  SurfaceFitOptions o;
  s.u[3] = 1.5;
  EXPECT_THROW(fit_surface(s.points, s.u, s.v, o), InputError);
  EXPECT_THROW(fit_surface(s.points, s.u.head(10), s.v, o), InputError);
}

}  // namespace
}  // namespace polarform
