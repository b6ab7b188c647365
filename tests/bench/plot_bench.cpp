// SVG rendering of dense figures: a scatter of n markers under a line, with a legend that must find
// a free place (or go beside the plot): the cost of mapping, decimating and placing.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "export/svg_plot.h"

namespace polarform {
namespace {

void BM_SvgDenseScatterWithLegend(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  Figure figure(900, 500);
  Plot& plot = figure.add_panel();
  Series cloud{"scanned points", {}, {}, Series::Style::markers, {}};
  Series fit{"fitted profile", {}, {}, Series::Style::line, {}};
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 360.0 * static_cast<double>(i) / static_cast<double>(n);
    cloud.x.push_back(t);
    cloud.y.push_back(std::sin(t / 30) + noise(rng));
    fit.x.push_back(t);
    fit.y.push_back(std::sin(t / 30));
  }
  plot.add(std::move(cloud));
  plot.add(std::move(fit));
  for (auto _ : state) benchmark::DoNotOptimize(svg_document(figure));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
}
BENCHMARK(BM_SvgDenseScatterWithLegend)->Arg(10000)->Arg(1000000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace polarform
