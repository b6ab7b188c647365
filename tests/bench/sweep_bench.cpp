// Revolution recovery of 10^6 mesh vertices on 2 threads (issue 18: ≤ 2 s): a stepped turned
// profile densified to 1000 vertices, each a ring of 1000 vertices on the exact circle, about a
// tilted, offset axis; PCA, ring-cluster axis refinement, profile, surface and the distances of
// all points. Label: the max distance (mm). Section recovery of a noisy torus segment (spec M9
// acceptance 1: spine radius 50, tube 5, 120°, σ = 0.01, 20 000 points); label: the station count
// and the rms (mm).
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include "designers/sweep/revolution_recovery.h"
#include "designers/sweep/section_recovery.h"

namespace polarform {
namespace {

Eigen::Matrix3Xd turned_ring_mesh(int rings, int segments) {
  const std::vector<Eigen::Vector2d> corners{{0, 0.1},     {0, 0.3},     {0.4, 0.3},  {0.7, 0.45},
                                             {1.0, 0.45},  {1.0, 0.38},  {1.1, 0.38}, {1.1, 0.45},
                                             {1.55, 0.45}, {1.55, 0.25}, {2.0, 0.25}};
  double length = 0;
  for (std::size_t i = 1; i < corners.size(); ++i) length += (corners[i] - corners[i - 1]).norm();
  const Eigen::Vector3d a = Eigen::Vector3d(0.2, -0.3, 1).normalized();
  const Eigen::Vector3d e1 = a.unitOrthogonal(), e2 = a.cross(e1), c(5, -7, 11);
  Eigen::Matrix3Xd P(3, static_cast<Eigen::Index>(rings) * segments);
  Eigen::Index k = 0;
  for (int i = 0; i < rings; ++i) {
    double s = length * i / (rings - 1);
    std::size_t j = 1;
    while (j + 1 < corners.size() && s > (corners[j] - corners[j - 1]).norm())
      s -= (corners[j] - corners[j - 1]).norm(), ++j;
    const Eigen::Vector2d q = corners[j - 1] + s * (corners[j] - corners[j - 1]).normalized();
    for (int t = 0; t < segments; ++t) {
      const double th = 2 * std::numbers::pi * t / segments;
      P.col(k++) = c + q.x() * a + q.y() * (std::cos(th) * e1 + std::sin(th) * e2);
    }
  }
  return P;
}

void BM_RevolutionRecovery(benchmark::State& state) {
  const Eigen::Matrix3Xd P = turned_ring_mesh(1000, static_cast<int>(state.range(0)) / 1000);
  RevolutionOptions o;
  o.threads = 2;
  o.tolerance = 1e-5;
  double max = 0;
  for (auto _ : state) {
    const RevolutionRecovery r = recover_revolution(P, o);
    max = r.error.max;
    benchmark::ClobberMemory();  // DoNotOptimize(double&) of benchmark 1.7.1 garbles the value
                                 // under GCC 12 -O3
  }
  char label[64];
  std::snprintf(label, sizeof label, "max distance %.3g mm", max);
  state.SetLabel(label);
}
BENCHMARK(BM_RevolutionRecovery)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SectionRecovery(benchmark::State& state) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.01);
  Eigen::Matrix3Xd P(3, state.range(0));
  for (Eigen::Index k = 0; k < P.cols(); ++k) {
    const double phi = 2 * std::numbers::pi / 3 * unit(rng), th = 2 * std::numbers::pi * unit(rng);
    const double rho = 5 + noise(rng);
    P.col(k) << (50 + rho * std::cos(th)) * std::cos(phi),
        (50 + rho * std::cos(th)) * std::sin(phi), rho * std::sin(th);
  }
  SectionOptions o;
  o.threads = 2;
  std::size_t stations = 0;
  double rms = 0;
  for (auto _ : state) {
    const SectionRecovery r = recover_sections(P, o);
    stations = r.stations.size();
    rms = r.error.rms;
    benchmark::ClobberMemory();
  }
  char label[64];
  std::snprintf(label, sizeof label, "%zu stations, rms %.3g mm", stations, rms);
  state.SetLabel(label);
}
BENCHMARK(BM_SectionRecovery)->Arg(20000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace polarform
