// Benchmarks of the cam conversion path: synthesis + conversion + verification of the roller
// example at 1 µm (issue 14's target: <= 5 ms; with the refit that makes the profile compact it
// measured 3.1–4.1 ms wall on the 2-core CI machine on 2026-12-06 (medians of 3 and 5
// repetitions, interleaved runs; 4.4–4.9 ms on the machine of the session before, where 1a9a818
// took 5.3–5.9 ms in the same periods — the VM's speed varies, and in its slowest periods both
// take 15–25 % longer) for 23 control points: the refit's degrees, fits and knot-removal tries run
// as tasks on both cores beside the product C = F·B, which alone takes 1.2–1.4 ms; callgrind
// counts 83.5 M instructions for the whole program run, about 30 M of them the program's start,
// against 103 M before the block Cholesky, the span-wise assembly and the R⁗ knots, and 260 M
// before the fits got cheaper, the placement kept its best round and the knot removals went the
// most removable first), one UI design update at 10 µm (target < 2 ms, measured 3.0–3.7 ms) and
// the degree-3 profile at 1 µm (5.4–5.9 ms).
#include <benchmark/benchmark.h>

#include <numbers>

#include "designers/cam/cam_analysis.h"
#include "designers/cam/cam_design.h"
#include "designers/cam/contour_polar_function.h"
#include "designers/convert/degree_limited.h"
#include "designers/convert/polar_conversion.h"
#include "src/units.h"

namespace polarform {
namespace {

double deg(double d) { return d * kRadiansPerDegree; }

CamDesign roller_example() {
  CamDesign d;
  d.follower = {FollowerKind::Roller, 0.0, 10.0};
  d.base_radius = 40;
  auto segment = [](SegmentKind kind, double from, double to, double lift, MotionLaw law) {
    SegmentSpec s;
    s.kind = kind, s.start = deg(from), s.end = deg(to), s.lift = lift, s.law = law;
    return s;
  };
  d.segments = {segment(SegmentKind::Dwell, 0, 90, 0, MotionLaw::Cycloidal),
                segment(SegmentKind::Rise, 90, 180, 20, MotionLaw::Cycloidal),
                segment(SegmentKind::Dwell, 180, 240, 0, MotionLaw::Cycloidal),
                segment(SegmentKind::Return, 240, 360, 20, MotionLaw::Polynomial4567)};
  return d;
}

void BM_RollerCamConversion1um(benchmark::State& state) {
  const CamDesign design = roller_example();
  ConversionOptions options;
  options.tolerance = 1e-3;  // mm: 1 µm
  for (auto _ : state) {
    const PlateCam cam = make_plate_cam(design);
    const PolarConversion c = convert_polar_function(cam_polar_function(cam), options);
    benchmark::DoNotOptimize(c.max_radial_error);
    state.counters["ctrl"] = c.curve.size();
    state.counters["arcs"] = static_cast<double>(c.arcs.size());
  }
}
BENCHMARK(BM_RollerCamConversion1um)->Unit(benchmark::kMillisecond);

// The same without the refit (Compaction::none): the product C = F·B built and measured, which
// the refit runs beside; the difference to BM_RollerCamConversion1um is what the compaction costs.
void BM_RollerCamProductOnly1um(benchmark::State& state) {
  const CamDesign design = roller_example();
  ConversionOptions options;
  options.tolerance = 1e-3;  // mm: 1 µm
  options.compaction = Compaction::none;
  for (auto _ : state) {
    const PlateCam cam = make_plate_cam(design);
    const PolarConversion c = convert_polar_function(cam_polar_function(cam), options);
    benchmark::DoNotOptimize(c.max_radial_error);
    state.counters["ctrl"] = c.curve.size();
  }
}
BENCHMARK(BM_RollerCamProductOnly1um)->Unit(benchmark::kMillisecond);

void BM_RollerCamDesignUpdate10um(benchmark::State& state) {
  const CamDesign design = roller_example();
  const std::vector<double> grid = uniform_angles(360);
  ConversionOptions options;
  options.tolerance = 10e-3;  // mm: 10 µm
  for (auto _ : state) {
    const PlateCam cam = make_plate_cam(design);
    const CamAnalysis analysis = analyse(cam, grid);
    const PolarConversion c = convert_polar_function(cam_polar_function(cam), options);
    benchmark::DoNotOptimize(analysis.max_pressure_angle);
    benchmark::DoNotOptimize(c.max_radial_error);
  }
}
BENCHMARK(BM_RollerCamDesignUpdate10um)->Unit(benchmark::kMillisecond);

// The design update's parts: analyses over 360 angles, the contour's polar function (its ψ(θ)
// table), and the conversion at 10 µm of a prepared polar function.
void BM_RollerCamAnalysis360(benchmark::State& state) {
  const PlateCam cam = make_plate_cam(roller_example());
  const std::vector<double> grid = uniform_angles(360);
  for (auto _ : state) benchmark::DoNotOptimize(analyse(cam, grid).max_pressure_angle);
}
BENCHMARK(BM_RollerCamAnalysis360)->Unit(benchmark::kMillisecond);

void BM_RollerCamPolarFunction(benchmark::State& state) {
  const PlateCam cam = make_plate_cam(roller_example());
  for (auto _ : state) benchmark::DoNotOptimize(cam_polar_function(cam).start);
}
BENCHMARK(BM_RollerCamPolarFunction)->Unit(benchmark::kMillisecond);

void BM_RollerCamContourEvaluation(benchmark::State& state) {
  const PolarFunction R = cam_polar_function(make_plate_cam(roller_example()));
  double psi = R.start;
  for (auto _ : state) {
    psi = psi + 0.001 > R.end ? R.start : psi + 0.001;
    benchmark::DoNotOptimize(R(psi));
  }
}
BENCHMARK(BM_RollerCamContourEvaluation);

void BM_RollerCamConvert10um(benchmark::State& state) {
  const PolarFunction R = cam_polar_function(make_plate_cam(roller_example()));
  ConversionOptions options;
  options.tolerance = 10e-3;  // mm
  for (auto _ : state) benchmark::DoNotOptimize(convert_polar_function(R, options).max_radial_error);
}
BENCHMARK(BM_RollerCamConvert10um)->Unit(benchmark::kMillisecond);

// The degree-3 profile (profile_deg3.dxf, --max-degree 3) of the roller example at 1 µm: knots by
// need, minimax refits and the measurement against R (issue 14: well under 50 ms).
void BM_RollerCamDegree3At1um(benchmark::State& state) {
  const PolarFunction R = cam_polar_function(make_plate_cam(roller_example()));
  for (auto _ : state) {
    const LimitedCurve c = approximate_polar_curve(R, 3, 1e-3);
    benchmark::DoNotOptimize(c.max_radial_error);
    state.counters["ctrl"] = c.control_points;
  }
}
BENCHMARK(BM_RollerCamDegree3At1um)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace polarform
