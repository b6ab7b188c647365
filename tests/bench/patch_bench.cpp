// Patch fitting benchmarks (spec B2, P6): the parametric LSQ surface fit of 20 000 points with a
// 16 × 16 bicubic net (target ≤ 0.1 s; FreeCAD's approxSurface takes about 55.7 s), and the
// parametrisation of 20 000 points on a 40 × 40 vertex blanket by grid3d search, quad projection
// and Newton polish on 2 threads (target ≤ 50 ms). Counters: the max distance (mm).
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>

#include "src/fit/quad_projection.h"
#include "src/fit/surface_fit.h"

namespace polarform {
namespace {

// A smooth doubly curved bicubic patch: 8 × 8 net over 100 × 80 mm with a wave of ±6 mm.
NurbsSurface wavy_patch() {
  const int n = 8;
  NurbsSurface::Points P(n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = 100.0 * i / (n - 1), y = 80.0 * j / (n - 1);
      P[i * n + j] = Eigen::Vector3d(x, y, 6 * std::sin(x / 20) * std::cos(y / 25) + 0.002 * x * y);
    }
  const Knots K = uniform_clamped_knots(3, n - 3, 0.0, 1.0);
  return NurbsSurface(3, 3, K, K, P);
}

struct Cloud {
  Eigen::Matrix3Xd points;
  Eigen::VectorXd u, v;
};

// n points at random parameters, moved along the normal by up to ±0.05 mm.
Cloud cloud(const NurbsSurface& s, int n) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> U(0.0, 1.0), O(-0.05, 0.05);
  Cloud c{Eigen::Matrix3Xd(3, n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (int k = 0; k < n; ++k) {
    c.u[k] = U(rng);
    c.v[k] = U(rng);
    c.points.col(k) = s.point(c.u[k], c.v[k]) + O(rng) * s.normal(c.u[k], c.v[k]);
  }
  return c;
}

void BM_SurfaceFit(benchmark::State& state, int points, int net) {
  const Cloud c = cloud(wavy_patch(), points);
  SurfaceFitOptions o;
  o.control_u = o.control_v = net;
  double max_distance = 0.0;
  for (auto _ : state) {
    const SurfaceFit f = fit_surface(c.points, c.u, c.v, o);
    max_distance = f.max_distance;
    benchmark::DoNotOptimize(f.surface);
  }
  state.counters["max_distance"] = max_distance;
}
BENCHMARK_CAPTURE(BM_SurfaceFit, 20000_16x16, 20000, 16)
    ->Name("BM_SurfaceFit/20000/16x16")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_PatchParametrize(benchmark::State& state) {
  const NurbsSurface s = wavy_patch();
  const Cloud c = cloud(s, static_cast<int>(state.range(0)));
  SurfaceBlanket b;
  const int n = 40;
  for (int a = 0; a < n; ++a) b.u.push_back(a / (n - 1.0)), b.v.push_back(a / (n - 1.0));
  b.points.resize(3, n * n);
  for (int a = 0; a < n; ++a)
    for (int d = 0; d < n; ++d) b.points.col(b.vertex(a, d)) = s.point(b.u[a], b.v[d]);
  double max_distance = 0.0;
  for (auto _ : state) {
    const PatchParameters p = parametrize_on_blanket(c.points, s, b);
    max_distance = p.distance.maxCoeff();
    benchmark::DoNotOptimize(p.u);
  }
  state.counters["max_distance"] = max_distance;
}
BENCHMARK(BM_PatchParametrize)->Arg(20000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace polarform
