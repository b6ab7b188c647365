// Kernel speed: rational curve and surface evaluation (ns per point over 10^6 parameters), the
// symbolic product of a quintic scalar B-spline with a 12-arc quasi-uniform quartic circle (Bae
// 2002, eq. (5.2)) at 200 knots (bench size) and 50 knots (a cam profile), and knot insertion.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>

#include "src/nurbs/knot_insertion.h"
#include "src/nurbs/nurbs_curve.h"
#include "src/nurbs/nurbs_surface.h"
#include "src/nurbs/symbolic_product.h"

namespace polarform {
namespace {

constexpr int kPoints = 1000000;
constexpr double kPi = std::numbers::pi;

Eigen::MatrixXd random_homogeneous(std::mt19937& rng, int dim, int n) {
  std::uniform_real_distribution<double> c(-1.0, 1.0), w(0.5, 2.0);
  Eigen::MatrixXd h(dim + 1, n);
  for (int j = 0; j < n; ++j) {
    h(dim, j) = w(rng);
    for (int i = 0; i < dim; ++i) h(i, j) = c(rng) * h(dim, j);
  }
  return h;
}

// Quasi-uniform quartic circle of `arcs` equal arcs: Bae 2002, eq. (5.2) with the printed α,
// parameter = angle, interior knots of multiplicity 4 at the arc ends.
NurbsCurve2d quartic_circle(int arcs) {
  const double phi = kPi / arcs, w = std::cos(phi), c = std::cos(phi / 5);
  const double alpha = (4 - 2 * c * c * c + c) / (-1 + 8 * c * c * c - 4 * c);
  const double a2 = alpha * alpha;
  const double wt[5] = {1, (1 + w) * alpha / 2, (a2 + a2 * w + w) / 3, (1 + w) * alpha / 2, 1};
  Knots U(5, 0.0);
  Eigen::MatrixXd h(3, 4 * arcs + 1);
  for (int j = 0; j < arcs; ++j) {
    const double t0 = 2 * phi * j, t1 = j + 1 < arcs ? t0 + 2 * phi : 2 * kPi;
    const Eigen::Vector2d b0(std::cos(t0), std::sin(t0)), b2(std::cos(t1), std::sin(t1));
    const Eigen::Vector2d b1 = Eigen::Vector2d(std::cos(t0 + phi), std::sin(t0 + phi)) / w;
    const Eigen::Vector2d q[5] = {
        b0, (b0 + w * b1) / (1 + w),
        (a2 * b0 + 2 * w * (1 + a2) * b1 + a2 * b2) / (2 * (a2 + a2 * w + w)),
        (b2 + w * b1) / (1 + w), b2};
    for (int i = 0; i < 5; ++i) h.col(4 * j + i) << wt[i] * q[i], wt[i];
    U.insert(U.end(), j + 1 < arcs ? 4 : 5, t1);
  }
  return NurbsCurve2d(BSpline(4, std::move(U), std::move(h)));
}

// A quintic scalar function on [0, 2π] with `knots` simple interior knots (a cam-like profile).
BSplineFunction quintic_profile(int knots) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> r(20.0, 25.0);
  Eigen::VectorXd f(knots + 6);
  for (Eigen::Index i = 0; i < f.size(); ++i) f(i) = r(rng);
  return BSplineFunction(5, uniform_clamped_knots(5, knots + 1, 0.0, 2 * kPi), f);
}

void BM_EvaluateRationalCurveDegree9(benchmark::State& state) {
  std::mt19937 rng(1);
  const NurbsCurve3d c(
      BSpline(9, uniform_clamped_knots(9, 30, 0.0, 1.0), random_homogeneous(rng, 3, 39)));
  for (auto _ : state) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int k = 0; k < kPoints; ++k) sum += c.point(k * (1.0 / (kPoints - 1)));
    benchmark::DoNotOptimize(sum);
  }
  state.counters["per_point"] = benchmark::Counter(
      kPoints, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_EvaluateRationalCurveDegree9)->Unit(benchmark::kMillisecond);

void BM_EvaluateRationalSurfaceDegree5x5(benchmark::State& state) {
  std::mt19937 rng(2);
  const Knots U = uniform_clamped_knots(5, 8, 0.0, 1.0);
  const NurbsSurface s(BSplineSurface(5, 5, U, U, random_homogeneous(rng, 3, 13 * 13)));
  for (auto _ : state) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int i = 0; i < 1000; ++i)
      for (int j = 0; j < 1000; ++j) sum += s.point(i * (1.0 / 999), j * (1.0 / 999));
    benchmark::DoNotOptimize(sum);
  }
  state.counters["per_point"] = benchmark::Counter(
      kPoints, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_EvaluateRationalSurfaceDegree5x5)->Unit(benchmark::kMillisecond);

// Bae 2002, eq. (A.2): F (quintic, range(0) interior knots) times the 12-arc quartic circle.
void BM_ProductQuinticTimesQuarticCircle(benchmark::State& state) {
  const BSplineFunction F = quintic_profile(static_cast<int>(state.range(0)));
  const NurbsCurve2d circle = quartic_circle(12);
  for (auto _ : state) benchmark::DoNotOptimize(product(F, circle));
  state.counters["degree"] = product(F, circle).degree();
  state.counters["control_points"] = product(F, circle).size();
}
BENCHMARK(BM_ProductQuinticTimesQuarticCircle)->Arg(200)->Arg(50)->Unit(benchmark::kMicrosecond);

void BM_InsertKnotQuintic200(benchmark::State& state) {
  const BSplineFunction F = quintic_profile(200);
  double u = 0.1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(insert_knot(F.spline(), u, 2));
    u = u < 6.0 ? u + 0.0137 : 0.1;
  }
}
BENCHMARK(BM_InsertKnotQuintic200)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace polarform
