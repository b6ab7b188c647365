// Pipe surfaces and the local self-intersection bound (MIT 13.472J §8.3.2, (8.41)–(8.46); spec
// M6–M7): the exact cylinder and torus against their closed forms, a skinned pipe around a sine
// spine measured independently, and κ_max against closed forms (parabola, helix, ellipse, circle)
// and against 10⁶ dense samples of cubic Béziers.
#include "src/nurbs/pipe_surface.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

#include "src/error.h"
#include "src/nurbs/curve_interpolation.h"
#include "src/nurbs/point_inversion.h"
#include "tests/src/nurbs/helix_spine.h"
#include "tests/src/nurbs/kernel_test_support.h"

namespace polarform {
namespace {

using std::numbers::pi;

// An arc of radius R about `centre` in the plane spanned by e1, e2 (orthonormal), from angle 0
// through `sweep` (≤ 2π), as rational quadratic arcs of at most 90° (NURBS Book A7.1).
NurbsCurve3d circle_arc(const Eigen::Vector3d& centre, const Eigen::Vector3d& e1,
                        const Eigen::Vector3d& e2, double R, double sweep) {
  const int arcs = static_cast<int>(std::ceil(sweep / (pi / 2) - 1e-12));
  const double step = sweep / arcs, w = std::cos(step / 2);
  NurbsCurve3d::Points P;
  std::vector<double> W;
  Knots U{0, 0, 0};
  for (int k = 0; k <= 2 * arcs; ++k) {
    const double a = k * step / 2, rho = k % 2 ? R / w : R;
    P.push_back(centre + rho * (std::cos(a) * e1 + std::sin(a) * e2));
    W.push_back(k % 2 ? w : 1.0);
  }
  for (int k = 1; k < arcs; ++k) U.insert(U.end(), 2, static_cast<double>(k) / arcs);
  U.insert(U.end(), 3, 1.0);
  return NurbsCurve3d(2, U, P, W);
}

// M6-1: line + circle = a cylinder of degree (2, 1): every point at distance r from the axis, the
// end circles at the spine's ends, the four quarter points 90° apart.
TEST(PipeSurface, LineSpineGivesAnExactCylinder) {
  const Eigen::Vector3d a(1, -2, 3), d = Eigen::Vector3d(2, 1, -2) / 3.0;  // |d| = 1
  const double L = 7.5, r = 1.25;
  const NurbsCurve3d spine(3, {0, 0, 0, 0, 2, 2, 2, 2},
                           NurbsCurve3d::Points{a, a + 1.0 * d, a + 4.0 * d, a + L * d});
  for (FrameRule rule : {FrameRule::rmf, FrameRule::fixed, FrameRule::frenet}) {
    const PipeSurface pipe = pipe_surface(spine, r, rule, 1e-4);
    EXPECT_TRUE(pipe.exact);
    EXPECT_EQ(pipe.max_error, 0.0);
    EXPECT_EQ(pipe.surface.degree_u(), 2);
    EXPECT_EQ(pipe.surface.degree_v(), 1);
    double worst = 0.0;
    for (int i = 0; i <= 64; ++i)
      for (int j = 0; j <= 16; ++j) {
        const Eigen::Vector3d q = pipe.surface(i / 64.0, 2.0 * j / 16) - a;
        worst = std::max(worst, std::abs((q - q.dot(d) * d).norm() - r));
      }
    EXPECT_LT(worst, 1e-12);
    const Eigen::Vector3d q0 = pipe.surface(0, 0) - a;
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR((pipe.surface(i / 4.0, 0.0) - a).dot(d), 0.0, 1e-12);
      EXPECT_NEAR((pipe.surface(i / 4.0, 2.0) - a).dot(d), L, 1e-12);
      EXPECT_NEAR((pipe.surface(i / 4.0, 0.0) - a).dot(q0), r * r * std::cos(i * pi / 2), 1e-12);
    }
  }
}

// M6-1 and M7-3: circle + circle = a torus piece of degree (2, 2), every point at distance r from
// the spine circle, spanning the spine's sweep; a full circle spine closes it.
TEST(PipeSurface, CircleSpineGivesAnExactTorus) {
  const Eigen::Vector3d centre(2, -1, 0.5);
  const Eigen::Vector3d e1 = Eigen::Vector3d(1, 2, 2) / 3.0;
  const Eigen::Vector3d e2 = Eigen::Vector3d(2, 1, -2) / 3.0, axis = e1.cross(e2);
  const double R = 4.0, r = 1.5;
  for (double sweep : {2 * pi, 1.5 * pi, 0.4 * pi, -0.7 * pi}) {
    const NurbsCurve3d spine =
        sweep > 0 ? circle_arc(centre, e1, e2, R, sweep) : circle_arc(centre, e1, -e2, R, -sweep);
    const FrameRule rule = sweep == 2 * pi ? FrameRule::frenet : FrameRule::rmf;
    const PipeSurface pipe = pipe_surface(spine, r, sweep < 1 ? FrameRule::fixed : rule, 1e-4);
    EXPECT_TRUE(pipe.exact);
    EXPECT_EQ(pipe.surface.degree_u(), 2);
    EXPECT_EQ(pipe.surface.degree_v(), 2);
    double worst = 0.0;
    for (int i = 0; i <= 64; ++i)
      for (int j = 0; j <= 64; ++j) {
        const Eigen::Vector3d q = pipe.surface(i / 64.0, j / 64.0) - centre;
        const double h = q.dot(axis), rho = (q - h * axis).norm();
        worst = std::max(worst, std::abs(std::hypot(rho - R, h) - r));
      }
    RecordProperty("torus_distance_error", test::sci(worst));
    EXPECT_LT(worst, 1e-12) << sweep;
    // The end sections are the circles of radius r in the normal planes at the spine's ends.
    for (int i = 0; i < 8; ++i) {
      const Eigen::Vector3d s0 = pipe.surface(i / 8.0, 0.0), s1 = pipe.surface(i / 8.0, 1.0);
      EXPECT_LT(std::abs((s0 - spine.point(0.0)).norm() - r), 1e-12);
      EXPECT_LT(std::abs((s0 - spine.point(0.0)).dot(spine.derivatives(0.0, 1)[1].normalized())),
                1e-12);
      EXPECT_LT(std::abs((s1 - spine.point(1.0)).norm() - r), 1e-12);
      EXPECT_LT(std::abs((s1 - spine.point(1.0)).dot(spine.derivatives(1.0, 1)[1].normalized())),
                1e-12);
    }
  }
}

// M7-3: the circle spine's κ_max = 1/R, so the pipe is locally regular exactly for r < R.
TEST(PipeSurface, CircleSpineIsLocallyRegularIffRadiusBelowSpineRadius) {
  const double R = 4.0;
  const NurbsCurve3d spine =
      circle_arc({0, 0, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), R, 2 * pi);
  const SpineCurvature k = max_curvature(spine);
  EXPECT_NEAR(k.kappa_max, 1.0 / R, 1e-15);
  EXPECT_TRUE(R * (1 - 1e-9) < 1.0 / k.kappa_max);
  EXPECT_FALSE(R * (1 + 1e-9) < 1.0 / k.kappa_max);
}

// A sine-like cubic spine, (t, 2 sin t, 0.3 cos t) through 13 points on [0, 2π].
NurbsCurve3d sine_spine() {
  Eigen::MatrixXd values(3, 13);
  Eigen::VectorXd t(13);
  for (int k = 0; k < 13; ++k) {
    t[k] = 2 * pi * k / 12;
    values.col(k) << t[k], 2 * std::sin(t[k]), 0.3 * std::cos(t[k]);
  }
  CubicEnds ends;  // the sine's own end tangents, so that the curvature vanishes nowhere
  ends.start_tangent = ends.end_tangent = Eigen::Vector3d(1, 2, 0);
  const BSpline s = interpolate_cubic(values, t, ends);
  Eigen::MatrixXd h(4, s.size());
  h << s.coefs(), Eigen::RowVectorXd::Ones(s.size());
  return NurbsCurve3d(BSpline(3, s.knots(), h));
}

// M6-3: the skinned pipe around the sine spine (r = 0.3) meets tol 1e-4 as it reports, with each
// frame rule, checked independently at 20000 random surface points (global closest points on the
// spine).
class SkinnedPipe : public ::testing::TestWithParam<FrameRule> {};

TEST_P(SkinnedPipe, AroundASineSpineMeetsTheTolerance) {
  const NurbsCurve3d spine = sine_spine();
  const double r = 0.3, tol = 1e-4;
  EXPECT_LT(r, 1.0 / max_curvature(spine).kappa_max);
  const PipeSurface pipe = pipe_surface(spine, r, GetParam(), tol);
  EXPECT_FALSE(pipe.exact);
  EXPECT_GT(pipe.sections, 4);
  EXPECT_LE(pipe.max_error, tol);
  RecordProperty("sections", pipe.sections);
  RecordProperty("max_error", test::sci(pipe.max_error));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1), v(spine.front(), spine.back());
  double worst = 0.0;
  for (int k = 0; k < 20000; ++k) {
    const Eigen::Vector3d p = pipe.surface(u(rng), v(rng));
    worst = std::max(worst, std::abs(closest_point(spine, p).distance - r));
  }
  RecordProperty("independent_max_error", test::sci(worst));
  EXPECT_LE(worst, tol);
  std::printf("sine pipe (rule %d): %d sections, reported %.3g, independent %.3g\n",
              static_cast<int>(GetParam()), pipe.sections, pipe.max_error, worst);
}

INSTANTIATE_TEST_SUITE_P(PipeSurface, SkinnedPipe,
                         ::testing::Values(FrameRule::rmf, FrameRule::frenet, FrameRule::fixed));

// Around a corner no number of stations reaches the tolerance: NumericalError with the numbers.
TEST(PipeSurface, CornerSpineCannotBeSkinnedToTolerance) {
  const NurbsCurve3d corner(1, {0, 0, 1, 2, 2},
                            NurbsCurve3d::Points{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
  try {
    pipe_surface(corner, 0.1, FrameRule::rmf, 1e-4);
    ADD_FAILURE() << "no NumericalError";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("4097 stations"), std::string::npos) << e.what();
  }
}

TEST(PipeSurface, Refusals) {
  const NurbsCurve3d spine = sine_spine();
  EXPECT_THROW(pipe_surface(spine, 0.0, FrameRule::rmf, 1e-4), InputError);
  EXPECT_THROW(pipe_surface(spine, 0.3, FrameRule::rmf, 0.0), InputError);
  // Frenet is undefined on the straight first spans of this cubic (collinear first points).
  const NurbsCurve3d straight_start(
      3, {0, 0, 0, 0, 1, 2, 3, 3, 3, 3},
      NurbsCurve3d::Points{{0, 0, 0}, {1, 1, 0}, {2, 2, 0}, {3, 3, 0}, {4, 4, 0}, {5, 3, 1}});
  EXPECT_THROW(pipe_surface(straight_start, 0.1, FrameRule::frenet, 1e-4), InputError);
}

// M7-1: the parabola y = x², x ∈ [−1, 1], as a quadratic Bézier: κ_max = 2 at x = 0 (t = 1/2).
TEST(SpineCurvature, ParabolaPeaksAtTheVertex) {
  const NurbsCurve3d parabola(2, {0, 0, 0, 1, 1, 1},
                              NurbsCurve3d::Points{{-1, 1, 0}, {0, -1, 0}, {1, 1, 0}});
  const SpineCurvature k = max_curvature(parabola);
  EXPECT_NEAR(k.kappa_max, 2.0, 1e-12);
  EXPECT_NEAR(parabola.point(k.t_at).x(), 0.0, 1e-12);
}

// M7-2: a helix has the constant κ = a/(a² + c²); its dense cubic spline reproduces it to 1e-6.
TEST(SpineCurvature, HelixCurvatureIsConstant) {
  const double a = 2.0, c = 0.5;
  const SpineCurvature k = max_curvature(test::helix_spline(a, c, 1.0, 4001));
  RecordProperty("helix_kappa_error", test::sci(std::abs(k.kappa_max - a / (a * a + c * c))));
  EXPECT_NEAR(k.kappa_max, a / (a * a + c * c), 1e-6);
}

// A rational piece: the ellipse arc (a cos φ, b sin φ), |φ| ≤ π/4, peaks at a/b² at φ = 0.
TEST(SpineCurvature, RationalEllipseArcPeaksAtTheMajorVertex) {
  const double a = 3.0, b = 1.0, w = std::cos(pi / 4);
  const NurbsCurve3d arc(2, {0, 0, 0, 1, 1, 1},
                         NurbsCurve3d::Points{{a * w, -b * w, 0}, {a / w, 0, 0}, {a * w, b * w, 0}},
                         {1, w, 1});
  const SpineCurvature k = max_curvature(arc);
  EXPECT_NEAR(k.kappa_max, a / (b * b), 1e-12);
  EXPECT_NEAR(k.t_at, 0.5, 1e-6);
}

// A corner (a C0 knot where the tangent turns) has unbounded curvature; a straight spine none.
TEST(SpineCurvature, CornerIsUnboundedAndALineIsFlat) {
  const NurbsCurve3d corner(1, {0, 0, 1, 2, 2},
                            NurbsCurve3d::Points{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
  const SpineCurvature k = max_curvature(corner);
  EXPECT_TRUE(std::isinf(k.kappa_max));
  EXPECT_EQ(k.t_at, 1.0);
  const NurbsCurve3d line(2, {0, 0, 0, 1, 1, 1},
                          NurbsCurve3d::Points{{0, 0, 0}, {1, 1, 1}, {3, 3, 3}});
  EXPECT_EQ(max_curvature(line).kappa_max, 0.0);
}

// M7-4: on random cubic Béziers (and a two-piece cubic B-spline), κ_max by root isolation equals
// the max over 10⁶ dense samples to 1e-9 relative and is never below it.
TEST(SpineCurvature, RootIsolationMatchesDenseSampling) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> c(-1, 1);
  for (int trial = 0; trial < 4; ++trial) {
    NurbsCurve3d::Points P(trial == 3 ? 5 : 4);
    for (auto& p : P) p = Eigen::Vector3d(c(rng), c(rng), c(rng));
    const Knots U = trial == 3 ? Knots{0, 0, 0, 0, 0.4, 1, 1, 1, 1} : Knots{0, 0, 0, 0, 1, 1, 1, 1};
    const NurbsCurve3d spine(3, U, P);
    const SpineCurvature k = max_curvature(spine);
    double dense = 0.0;
    constexpr int samples = 1000000;
    for (int s = 0; s <= samples; ++s) {
      const auto d = spine.derivatives(static_cast<double>(s) / samples, 2);
      dense = std::max(dense, d[1].cross(d[2]).norm() / std::pow(d[1].norm(), 3));
    }
    RecordProperty("relative_gap_" + std::to_string(trial),
                   test::sci((k.kappa_max - dense) / k.kappa_max));
    EXPECT_GE(k.kappa_max, dense * (1 - 1e-14)) << trial;
    EXPECT_LE(k.kappa_max - dense, 1e-9 * k.kappa_max) << trial;
  }
}

}  // namespace
}  // namespace polarform
