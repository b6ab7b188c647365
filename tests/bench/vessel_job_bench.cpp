// The whole vessel job on each bundled example (examples/vessels): read nothing, write nothing —
// synthesis, analyses, preset comparison, conversion to the project's tolerance and the revolved
// surfaces, as `polarform vessel` computes them (issue budget: full run under 200 ms).
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "jobs/vessel/vessel_job.h"

namespace polarform {
namespace {

void BM_VesselJob(benchmark::State& state, const std::string& example) {
  std::vector<std::string> warnings;
  const VesselProject project = read_vessel_project(
      std::string(POLARFORM_SOURCE_DIR) + "/examples/vessels/" + example, warnings);
  int control_points = 0, arcs = 0;
  double error = 0.0;
  for (auto _ : state) {
    const VesselJobResult r = run_vessel_job(project);
    control_points = r.converted.conversion->curve.size();
    arcs = static_cast<int>(r.converted.conversion->arcs.size());
    error = r.converted.conversion->max_radial_error;
    benchmark::DoNotOptimize(r.converted.surfaces.head.size_v());
  }
  state.counters["control_points"] = control_points;
  state.counters["arcs"] = arcs;
  state.counters["error_um"] = error * 1e3;
}
BENCHMARK_CAPTURE(BM_VesselJob, hemispherical, std::string("hemispherical.xml"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VesselJob, ellipsoidal_2_1, std::string("ellipsoidal_2_1.xml"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VesselJob, torispherical_100_6, std::string("torispherical_100_6.xml"))
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VesselJob, custom_curvature, std::string("custom_curvature.xml"))
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace polarform
