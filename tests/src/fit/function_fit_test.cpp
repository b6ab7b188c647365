// The least-squares engine of the fitters: sparse normal equations against a dense assembly, the
// thin-plate energy against closed forms, exact recovery of known B-spline functions (open,
// periodic, with pole conditions), fairness over holes, GCV on noisy data, adaptive refinement to a
// tolerance, and the error statistics.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "src/error.h"
#include "src/fit/coefficient_map.h"
#include "src/fit/error_stats.h"
#include "src/fit/fairness.h"
#include "src/fit/function_fit.h"
#include "src/fit/normal_equations.h"
#include "src/fit/spline_axis.h"
#include "src/nurbs/basis.h"
#include "src/nurbs/periodic.h"
#include "tests/src/fit/fit_test_support.h"

namespace polarform {
namespace {

std::vector<double> uniform(int spans, double a, double b) {
  std::vector<double> out;
  for (int s = 0; s <= spans; ++s) out.push_back(a + (b - a) * s / spans);
  return out;
}

Samples random_samples(std::size_t n, double u0, double u1, double v0, double v1, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(u0, u1), V(v0, v1);
  Samples s;
  s.u.resize(n), s.v.resize(n), s.value.resize(n);
  for (std::size_t k = 0; k < n; ++k) s.u[k] = U(rng), s.v[k] = V(rng);
  return s;
}

TEST(ErrorStats, PercentilesByNearestRank) {
  Eigen::VectorXd d(200);
  for (int i = 0; i < 200; ++i) d[i] = (i % 2 ? -1.0 : 1.0) * (i + 1);  // |d| = 1..200
  const ErrorStats s = error_stats(d);
  EXPECT_EQ(s.count, 200u);
  EXPECT_DOUBLE_EQ(s.max, 200.0);
  EXPECT_DOUBLE_EQ(s.p99, 198.0);  // ceil(0.99 · 200) = 198
  EXPECT_DOUBLE_EQ(s.p95, 190.0);
  EXPECT_DOUBLE_EQ(s.mean, 100.5);
  EXPECT_NEAR(s.rms, std::sqrt(200.0 * 201.0 * 401.0 / 6.0 / 200.0), 1e-12);
  EXPECT_DOUBLE_EQ(abs_quantile(d, 0.5), 100.0);
}

TEST(NormalEquations, MatchDenseAssemblyWithPeriodicFolding) {
  const SplineAxis U = clamped_axis(2, {0.0, 0.3, 0.5, 1.0});
  const SplineAxis V = periodic_axis(3, uniform(5, 0.0, 2.0));
  const CoefficientMap map(U.size(), V.size(), V.distinct(), false, false);
  Samples s = random_samples(300, 0.0, 1.0, 0.0, 2.0, 7);
  s.weight = Eigen::VectorXd::LinSpaced(300, 0.5, 2.0);
  for (int k = 0; k < 300; ++k) s.value[k] = std::sin(3 * s.u[k]) + s.v[k];
  const NormalEquations ne = assemble_normal_equations(U, V, map, s, 2);
  // Dense: B (samples x unknowns) with folded columns.
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(300, map.unknowns());
  for (int k = 0; k < 300; ++k) {
    const int su = find_span(U.degree, U.knots, U.size(), s.u[k]);
    const int sv = find_span(V.degree, V.knots, V.size(), s.v[k]);
    double Nu[4], Nv[4];
    basis_funs(su, s.u[k], U.degree, U.knots, Nu);
    basis_funs(sv, s.v[k], V.degree, V.knots, Nv);
    for (int a = 0; a <= U.degree; ++a)
      for (int b = 0; b <= V.degree; ++b) B(k, map(su - U.degree + a, sv - V.degree + b)) += Nu[a] * Nv[b];
  }
  const Eigen::MatrixXd W = s.weight.asDiagonal();
  EXPECT_LT((Eigen::MatrixXd(ne.A) - B.transpose() * W * B).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((ne.b - B.transpose() * W * s.value).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_NEAR(ne.gg, s.value.dot(W * s.value), 1e-10);
  EXPECT_NEAR(ne.weight_sum, s.weight.sum(), 1e-12);
  EXPECT_EQ(map.unknowns(), U.size() * 5);
}

// Coefficients of g(s, t) in the space by least squares on a dense grid (exact for splines in it).
Eigen::VectorXd coefficients_of(const SplineAxis& U, const SplineAxis& V,
                                const std::function<double(double, double)>& g) {
  Samples s;
  const int m = 40;
  s.u.resize(m * m), s.v.resize(m * m), s.value.resize(m * m);
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b) {
      const int k = a * m + b;
      s.u[k] = U.front() + (U.back() - U.front()) * a / (m - 1);
      s.v[k] = V.front() + (V.back() - V.front()) * b / (m - 1);
      s.value[k] = g(s.u[k], s.v[k]);
    }
  const CoefficientMap map(U.size(), V.size());
  const NormalEquations ne = assemble_normal_equations(U, V, map, s);
  return Eigen::MatrixXd(ne.A).ldlt().solve(ne.b);
}

TEST(Fairness, ThinPlateEnergyOfQuadraticsOnTheUnitSquare) {
  // Domain [2, 5] x [-1, 1] maps to the unit square: s = (u − 2)/3, t = (v + 1)/2.
  const SplineAxis U = clamped_axis(3, {2.0, 3.0, 3.5, 5.0}), V = clamped_axis(3, uniform(3, -1.0, 1.0));
  const CoefficientMap map(U.size(), V.size());
  const Eigen::SparseMatrix<double> T = thin_plate_matrix(U, V, map);
  auto energy = [&](const std::function<double(double, double)>& g) {
    const Eigen::VectorXd x = coefficients_of(U, V, g);
    return x.dot(T * x);
  };
  auto S = [](double u) { return (u - 2.0) / 3.0; };
  auto Tt = [](double v) { return (v + 1.0) / 2.0; };
  EXPECT_NEAR(energy([&](double u, double) { return S(u) * S(u); }), 4.0, 1e-9);   // F_ss = 2
  EXPECT_NEAR(energy([&](double, double v) { return Tt(v) * Tt(v); }), 4.0, 1e-9);
  EXPECT_NEAR(energy([&](double u, double v) { return S(u) * Tt(v); }), 2.0, 1e-9);  // 2 F_st²
  EXPECT_NEAR(energy([&](double u, double v) { return 3 * S(u) - Tt(v) + 7; }), 0.0, 1e-9);
  // Cubic s³: ∫ (6s)² ds = 12.
  EXPECT_NEAR(energy([&](double u, double) { return std::pow(S(u), 3); }), 12.0, 1e-9);
}

// A random bicubic spline function on given axes; the samples are its exact values.
struct KnownSpline {
  BSplineSurface F;
  Samples samples;
};

KnownSpline known(const SplineAxis& U, const SplineAxis& V, std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> c(5.0, 9.0);
  Eigen::MatrixXd coef(1, U.size() * V.size());
  for (Eigen::Index k = 0; k < coef.cols(); ++k) coef(0, k) = c(rng);
  BSplineSurface F(U.degree, V.degree, U.knots, V.knots, coef);
  Samples s = random_samples(n, U.front(), U.back(), V.front(), V.back(), seed + 1);
  for (std::size_t k = 0; k < n; ++k) F.point(s.u[k], s.v[k], &s.value[k]);
  return {F, s};
}

FunctionFitOptions exact_options(int nu, int nv) {
  FunctionFitOptions o;
  o.size_u = nu, o.size_v = nv;
  o.placement = KnotPlacement::uniform;
  o.fairness.mode = FairnessOptions::Mode::fixed;
  o.fairness.weight = 0.0;
  return o;
}

TEST(FunctionFit, RecoversAKnownBicubicSurfaceToRoundOff) {
  const SplineAxis U = clamped_axis(3, uniform(5, 0.0, 2.0)), V = clamped_axis(3, uniform(4, 1.0, 3.0));
  const KnownSpline k = known(U, V, 5000, 3);
  const FunctionFitResult r = fit_function(k.samples, {0.0, 2.0, 1.0, 3.0}, exact_options(8, 7));
  EXPECT_EQ(r.F.knots_u(), U.knots);
  EXPECT_EQ(r.F.knots_v(), V.knots);
  EXPECT_LT((r.F.coefs() - k.F.coefs()).cwiseAbs().maxCoeff(), 1e-11);
  EXPECT_LT(r.stats.max, 1e-11);
  EXPECT_FALSE(r.reduced_u || r.reduced_v);
}

TEST(FunctionFit, PeriodicFitIsClosedAndRecoversAPeriodicSpline) {
  const SplineAxis U = clamped_axis(3, uniform(3, 0.0, 1.0));
  const std::vector<double> br = uniform(6, 0.0, 2 * std::numbers::pi);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> c(5.0, 9.0);
  // F̃ = periodic in v: coefficient rows of 6 distinct values.
  Eigen::MatrixXd distinct(U.size(), 6);
  for (Eigen::Index k = 0; k < distinct.size(); ++k) distinct(k) = c(rng);
  const BSpline along_v = periodic_bspline(3, br, distinct.transpose().eval().transpose());
  const BSplineSurface Ft = BSplineSurface::from_along_v(along_v, 3, U.knots, 1);
  Samples s = random_samples(6000, 0.0, 1.0, 0.0, 2 * std::numbers::pi, 5);
  for (int k = 0; k < 6000; ++k) Ft.point(s.u[k], s.v[k], &s.value[k]);
  FunctionSpace sp{0.0, 1.0, 0.0, 2 * std::numbers::pi, true};
  const FunctionFitResult r = fit_function(s, sp, exact_options(6, 6));
  EXPECT_LT(r.stats.max, 1e-11);
  // Clipped to a clamped F on [0, 2π] whose two ends agree with all derivatives up to q − 1 = 2.
  EXPECT_EQ(r.F.knots_v().front(), 0.0);
  EXPECT_EQ(r.F.knots_v()[3], 0.0);
  for (double u : {0.0, 0.37, 1.0}) {
    const Eigen::MatrixXd d0 = r.F.derivatives(u, 0.0, 2), d1 = r.F.derivatives(u, 2 * std::numbers::pi, 2);
    EXPECT_NEAR(d0(0, 0), d1(0, 0), 1e-12);  // F
    EXPECT_NEAR(d0(0, 1), d1(0, 1), 1e-10);  // F_v
    EXPECT_NEAR(d0(0, 2), d1(0, 2), 1e-9);   // F_vv
    double f;
    Ft.point(u, 1.0, &f);
    EXPECT_NEAR(r.F.point(u, 1.0)[0], f, 1e-11);
  }
}

TEST(FunctionFit, PoleConditionsTieTheFirstTwoRows) {
  const SplineAxis U = clamped_axis(3, uniform(4, 0.0, 1.0)), V = clamped_axis(3, uniform(4, 0.0, 1.0));
  const KnownSpline k = known(U, V, 3000, 9);
  FunctionSpace sp{0.0, 1.0, 0.0, 1.0, false, false, 2, 2};
  FunctionFitOptions o = exact_options(7, 7);
  const FunctionFitResult r = fit_function(k.samples, sp, o);
  const Eigen::MatrixXd& c = r.F.coefs();
  const int nv = r.F.size_v(), nu = r.F.size_u();
  for (int j = 0; j < nv; ++j) {
    EXPECT_EQ(c(0, j), c(0, 0));               // (3.14a)
    EXPECT_EQ(c(0, nv + j), c(0, 0));          // (3.14b)
    EXPECT_EQ(c(0, (nu - 1) * nv + j), c(0, (nu - 2) * nv));
  }
  // F is constant along u = 0 and F_u vanishes there (Bae 2002, (D.1), (D.3a)).
  const Eigen::MatrixXd d0 = r.F.derivatives(0.0, 0.2, 1), d1 = r.F.derivatives(0.0, 0.9, 1);
  EXPECT_NEAR(d0(0, 0), d1(0, 0), 1e-13);
  EXPECT_NEAR(d0(0, 2), 0.0, 1e-12);
}

TEST(FunctionFit, FairnessBridgesAHoleThatPlainLeastSquaresCannot) {
  Samples s = random_samples(20000, 0.0, 1.0, 0.0, 1.0, 13);
  // Remove a disc of radius 0.2 and fit a smooth function of the rest.
  std::vector<int> keep;
  for (int k = 0; k < 20000; ++k)
    if (std::hypot(s.u[k] - 0.5, s.v[k] - 0.5) > 0.2) keep.push_back(k);
  Samples h;
  h.u.resize(keep.size()), h.v.resize(keep.size()), h.value.resize(keep.size());
  auto g = [](double u, double v) { return 10 + std::sin(2 * u) + v * v; };
  for (std::size_t a = 0; a < keep.size(); ++a) {
    h.u[a] = s.u[keep[a]], h.v[a] = s.v[keep[a]];
    h.value[a] = g(h.u[a], h.v[a]);
  }
  FunctionFitOptions o = exact_options(20, 20);
  EXPECT_THROW(fit_function(h, {}, o), NumericalError);
  o.fairness = FairnessOptions{};  // relative, 1e-7
  const FunctionFitResult r = fit_function(h, {}, o);
  EXPECT_LT(r.stats.max, 1e-4);
  double worst = 0.0;
  for (double u = 0.35; u <= 0.65; u += 0.01)
    for (double v = 0.35; v <= 0.65; v += 0.01) worst = std::max(worst, std::abs(r.F.point(u, v)[0] - g(u, v)));
  EXPECT_LT(worst, 1e-3);  // the smooth function is bridged, not blown up
}

TEST(FunctionFit, GcvOnNoisyDataLeavesResidualsAtTheNoiseLevel) {
  const double sigma = 0.05;
  Samples s = random_samples(20000, 0.0, 1.0, 0.0, 1.0, 17);
  std::mt19937 rng(19);
  std::normal_distribution<double> N(0.0, sigma);
  auto g = [](double u, double v) { return 10 + std::sin(6 * u) * std::cos(4 * v); };
  for (int k = 0; k < 20000; ++k) s.value[k] = g(s.u[k], s.v[k]) + N(rng);
  FunctionFitOptions o;
  o.size_u = o.size_v = 30;
  o.fairness.mode = FairnessOptions::Mode::gcv;
  const FunctionFitResult r = fit_function(s, {}, o);
  EXPECT_GT(r.lambda, 0.0);
  EXPECT_GT(r.dof, 20.0);
  EXPECT_LT(r.dof, 900.0);
  EXPECT_NEAR(r.stats.rms, sigma, 0.05 * sigma);
  RecordProperty("lambda", test::sci(r.lambda));
  RecordProperty("dof", test::sci(r.dof));
  double truth2 = 0.0;
  const int m = 50;
  for (int a = 0; a < m; ++a)
    for (int b = 0; b < m; ++b) {
      const double u = (a + 0.5) / m, v = (b + 0.5) / m;
      truth2 += std::pow(r.F.point(u, v)[0] - g(u, v), 2);
    }
  EXPECT_LT(std::sqrt(truth2 / (m * m)), 0.3 * sigma);  // smoother than the noise
}

TEST(FunctionFit, RefinesToATolerance) {
  Samples s = random_samples(20000, 0.0, 1.0, 0.0, 1.0, 23);
  auto g = [](double u, double v) { return std::exp(u) * std::sin(3 * v) + 4; };
  for (int k = 0; k < 20000; ++k) s.value[k] = g(s.u[k], s.v[k]);
  FunctionFitOptions o;
  o.tolerance = 1e-4;
  o.fairness.mode = FairnessOptions::Mode::fixed;
  o.fairness.weight = 0.0;
  const FunctionFitResult r = fit_function(s, {}, o);
  EXPECT_LE(r.stats.max, 1e-4);
  EXPECT_GT(r.refinements, 0);
  EXPECT_LT(r.size_u * r.size_v, 400);
  // Noise of σ = 0.01 cannot be fitted to a max error of 1e-4 within a 20 x 20 limit.
  std::mt19937 rng(29);
  std::normal_distribution<double> N(0.0, 0.01);
  for (int k = 0; k < 20000; ++k) s.value[k] += N(rng);
  o.max_size_u = o.max_size_v = 20;
  o.fairness = FairnessOptions{};
  EXPECT_THROW(fit_function(s, {}, o), NumericalError);
}

TEST(FunctionFit, ConstantDataReducesToDegreeZero) {
  Samples s = random_samples(2000, 0.0, 1.0, 0.0, 1.0, 31);
  for (int k = 0; k < 2000; ++k) s.value[k] = 3.0 + 2.0 * s.u[k] * s.u[k];  // constant along v
  FunctionFitOptions o = exact_options(6, 6);
  const FunctionFitResult r = fit_function(s, {}, o);
  EXPECT_TRUE(r.reduced_v);
  EXPECT_FALSE(r.reduced_u);
  EXPECT_EQ(r.F.degree_v(), 0);
  EXPECT_EQ(r.F.degree_u(), 3);
  EXPECT_LT(r.stats.max, 1e-12);
}

TEST(FunctionFit, CurveFunctionRecoversAPeriodicCurveAndReportsProgress) {
  const std::vector<double> br = uniform(8, 1.0, 4.0);
  Eigen::MatrixXd c(1, 8);
  c << 3, 4, 2, 5, 4, 3, 6, 2;
  const BSpline truth = periodic_bspline(3, br, c);
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> U(1.0, 4.0);
  Eigen::VectorXd u(500), g(500);
  for (int k = 0; k < 500; ++k) u[k] = U(rng), g[k] = truth.point(u[k])[0];
  FunctionFitOptions o = exact_options(0, 8);
  std::vector<double> seen;
  o.progress = [&](double x) { seen.push_back(x); };
  const CurveFunctionFit f = fit_curve_function(u, g, 1.0, 4.0, true, o);
  EXPECT_EQ(f.F.degree(), 3);
  EXPECT_EQ(f.size, 8);
  EXPECT_LT(f.stats.max, 1e-12);
  for (double x = 1.0; x <= 4.0; x += 0.01) EXPECT_NEAR(f.F(x), truth.point(x)[0], 1e-12);
  EXPECT_NEAR(f.F.derivatives(1.0, 2)[1], f.F.derivatives(4.0, 2)[1], 1e-10);  // closed, C²
  ASSERT_FALSE(seen.empty());
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_DOUBLE_EQ(seen.back(), 1.0);
}

TEST(FunctionFit, RejectsBadInput) {
  Samples s = random_samples(100, 0.0, 1.0, 0.0, 1.0, 37);
  s.value.setOnes();
  FunctionFitOptions o;
  o.degree_u = -1;
  EXPECT_THROW(fit_function(s, {}, o), InputError);
  o = FunctionFitOptions{};
  s.value[3] = NAN;
  EXPECT_THROW(fit_function(s, {}, o), InputError);
  s.value[3] = 1.0;
  s.weight = Eigen::VectorXd::Ones(99);
  EXPECT_THROW(fit_function(s, {}, o), InputError);
}

}  // namespace
}  // namespace polarform
