// Cam designer speed: the UI rebuilds the program, the roller contour's PolarFunction and the
// analyses at 720 angles on every edit, so the whole round must stay well under a millisecond.
#include <benchmark/benchmark.h>

#include <numbers>

#include "designers/cam/cam_analysis.h"
#include "designers/cam/contour_polar_function.h"
#include "designers/cam/plate_cam.h"
#include "src/units.h"

namespace polarform {
namespace {

SegmentSpec segment(SegmentKind kind, double from_deg, double to_deg, double lift, MotionLaw law) {
  SegmentSpec s;
  s.kind = kind;
  s.start = from_deg * kRadiansPerDegree;
  s.end = to_deg * kRadiansPerDegree;
  s.lift = lift;
  s.law = law;
  return s;
}

// Dwell - rise - dwell - return, roller follower, full analysis on a 0.5° grid.
void BM_CamEditRoundTrip(benchmark::State& state) {
  const std::vector<double> grid = uniform_angles(720);
  for (auto _ : state) {
    const CamProgram program({segment(SegmentKind::Dwell, 0, 60, 0, MotionLaw::Cycloidal),
                              segment(SegmentKind::Rise, 60, 170, 18, MotionLaw::ModifiedSine),
                              segment(SegmentKind::Dwell, 170, 230, 0, MotionLaw::Cycloidal),
                              segment(SegmentKind::Return, 230, 360, 18, MotionLaw::Polynomial345)});
    const PlateCam cam(program, {FollowerKind::Roller, 5.0, 12.0}, 45.0);
    const PolarFunction contour = cam_polar_function(cam);
    const CamAnalysis analysis = analyse(cam, grid);
    benchmark::DoNotOptimize(contour(1.0));
    benchmark::DoNotOptimize(analysis.max_pressure_angle.value);
  }
  state.SetLabel("program + roller contour PolarFunction + analyses at 720 angles");
}
BENCHMARK(BM_CamEditRoundTrip)->Unit(benchmark::kMicrosecond);

// Evaluating the contour PolarFunction (Newton inversion + exact derivatives up to R''').
void BM_ContourPolarFunctionEvaluation(benchmark::State& state) {
  const CamProgram program({segment(SegmentKind::Dwell, 0, 60, 0, MotionLaw::Cycloidal),
                            segment(SegmentKind::Rise, 60, 170, 18, MotionLaw::ModifiedSine),
                            segment(SegmentKind::Dwell, 170, 230, 0, MotionLaw::Cycloidal),
                            segment(SegmentKind::Return, 230, 360, 18, MotionLaw::Polynomial345)});
  const PolarFunction contour = cam_polar_function(PlateCam(program, {FollowerKind::Roller, 5.0, 12.0}, 45.0));
  double psi = contour.start, out[4];
  for (auto _ : state) {
    contour.derivatives(psi, 3, out);
    benchmark::DoNotOptimize(out[3]);
    psi += 0.01;
    if (psi > contour.end) psi = contour.start;
  }
}
BENCHMARK(BM_ContourPolarFunctionEvaluation)->Unit(benchmark::kNanosecond);

}  // namespace
}  // namespace polarform
