// The patch pipeline end to end on 2 threads (issue 20: 20 000 points on a 16 × 16 bicubic net
// ≤ 0.5 s; 10^6 points ≤ 5 s): the S8(a) patch sampled at random parameters with 1e-4·diag noise,
// its exact boundary, the bilinear Coons base, the 0.5 % blanket, the grid search with polish, a
// 16 × 16 fixed-boundary fit with 3 correction rounds and the distances of all points. Label: the
// max distance (mm) and the quads.
#include <benchmark/benchmark.h>

#include <cstdio>

#include "designers/patch/patch_fit.h"
#include "tests/support/src/synthetic_patches.h"

namespace polarform {
namespace {

void BM_PatchPipeline(benchmark::State& state) {
  const NurbsSurface truth = patch_test::s8_patch('a');
  const auto sample =
      patch_test::sample_patch(truth, static_cast<int>(state.range(0)), 1e-4 * 14.0);
  const PatchBoundary boundary = patch_test::exact_boundary(truth);
  PatchFitOptions o;
  o.control_u = o.control_v = 16;
  o.correction_rounds = 3;
  o.threads = 2;
  PatchFit r;
  for (auto _ : state) {
    r = fit_patch(sample.points, boundary, o);
    benchmark::ClobberMemory();  // not DoNotOptimize(double&): it garbles the value (GCC 12 -O3)
  }
  char label[96];
  std::snprintf(label, sizeof label, "max %.3g mm, %d quads", r.error.max,
                r.decomposition.blanket.quads());
  state.SetLabel(label);
}
BENCHMARK(BM_PatchPipeline)->Arg(20000)->Arg(1000000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace polarform
