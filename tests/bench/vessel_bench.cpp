// Vessel designer speed (issue budget): the synthesis with 50 curvature targets and 20 ordinates
// under 50 ms, and the full run — synthesis, analyses, conversion to the tolerance and the
// revolved surfaces — under 200 ms, with the 2:1 ellipsoidal head's curvature as the targets;
// and the heaviest example, the 100 %/6 % torispherical alternative.
#include <benchmark/benchmark.h>

#include "designers/convert/polar_conversion.h"
#include "designers/vessel/curvature_synthesis.h"
#include "designers/vessel/vessel_design.h"
#include "designers/vessel/vessel_surfaces.h"

namespace polarform {
namespace {

VesselDesign ellipsoidal_design() {
  VesselDesign d;
  d.radius = 500;
  d.length = 1500;
  d.thickness = 10;
  d.pressure = 2;
  d.preset = HeadPreset{HeadKind::ellipsoidal, 2.0};
  d.preset_targets = 50;
  d.end_a = d.end_b = EndCondition{500.0, 0.0, 500.0};  // κ = 0 at the junctions
  return d;
}

void BM_VesselSynthesis50Targets20Ordinates(benchmark::State& state) {
  SynthesisProblem problem;
  problem.length_unit = 500;
  problem.targets = preset_targets(head_shape({HeadKind::ellipsoidal, 2.0}, 500), 50);
  problem.end_a = problem.end_b = EndCondition{500.0, 0.0, 500.0};
  int iterations = 0;
  for (auto _ : state) {
    const SynthesisResult r = synthesize_profile(problem);
    iterations = r.iterations;
    benchmark::DoNotOptimize(r.objective);
  }
  state.counters["evaluations"] = iterations;
}
BENCHMARK(BM_VesselSynthesis50Targets20Ordinates)->Unit(benchmark::kMillisecond);

void BM_VesselFullRun(benchmark::State& state) {
  const VesselDesign design = ellipsoidal_design();
  ConversionOptions options;
  options.tolerance = 1e-3;
  int arcs = 0;
  for (auto _ : state) {
    const VesselSolution s = solve_vessel(design);
    const PolarConversion c = convert_polar_function(s.profile, options);
    const VesselSurfaces v = vessel_surfaces(c.curve, design.length);
    arcs = static_cast<int>(c.arcs.size());
    benchmark::DoNotOptimize(v.head.size_v());
  }
  state.counters["arcs"] = arcs;
  state.SetLabel("solve + stresses + preset comparison + conversion to 1 µm + revolve");
}
BENCHMARK(BM_VesselFullRun)->Unit(benchmark::kMillisecond);

// The heaviest example (examples/vessels/torispherical_100_6.xml): 180 targets, 60 ordinates.
void BM_VesselTorisphericalExample(benchmark::State& state) {
  VesselDesign design = ellipsoidal_design();
  design.preset = torispherical_100_6(500);
  design.preset_targets = 180;
  design.end_a = design.end_b = EndCondition{500.0, 0.0, 500.0 - 500.0 * 500.0 / 60.0};
  design.synthesis.ordinates = 60;
  design.synthesis.symmetric = true;
  ConversionOptions options;
  options.tolerance = 1e-3;
  int evaluations = 0, arcs = 0;
  for (auto _ : state) {
    const VesselSolution s = solve_vessel(design);
    const PolarConversion c = convert_polar_function(s.profile, options);
    const VesselSurfaces v = vessel_surfaces(c.curve, design.length);
    evaluations = s.synthesis.iterations;
    arcs = static_cast<int>(c.arcs.size());
    benchmark::DoNotOptimize(v.head.size_v());
  }
  state.counters["evaluations"] = evaluations;
  state.counters["arcs"] = arcs;
}
BENCHMARK(BM_VesselTorisphericalExample)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace polarform
