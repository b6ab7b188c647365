// The study's peer columns (issue 14): one row of the study job on examples/cams/roller.xml at
// 1 µm with the peers' fits (Open CASCADE's degree 3 and degrees 3..8, SISL's degree 3 and best of
// degrees 3..8) and without them, so that the peers' cost shows as the difference.
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "jobs/study/study_job.h"

namespace polarform {
namespace {

void BM_StudyPeerColumns(benchmark::State& state, bool peers) {
  std::vector<std::string> warnings;
  const CamProject project =
      read_cam_project(std::string(POLARFORM_SOURCE_DIR) + "/examples/cams/roller.xml", warnings);
  StudyRow row;
  for (auto _ : state) {
    const StudyJobResult r = run_study_job(project, {1e-3}, {}, StudyOptions{peers});
    row = r.rows.front();
    benchmark::DoNotOptimize(row.exact.max_radial_error);
  }
  state.counters["exact"] = row.exact.control_points;
  state.counters["degree3"] = row.degree3.control_points;
  if (row.peers) {
    state.counters["occt3"] = row.occt_degree3.control_points;
    state.counters["occt3_8"] = row.occt_best.control_points;
    state.counters["sisl3"] = row.sisl_degree3.control_points;
    state.counters["sisl3_8"] = row.sisl_best.control_points;
  }
}
BENCHMARK_CAPTURE(BM_StudyPeerColumns, with_peers, true)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK_CAPTURE(BM_StudyPeerColumns, without_peers, false)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);

}  // namespace
}  // namespace polarform
