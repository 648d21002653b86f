// The parts' axial elements (surfaces/cylindrical/elastic/axial_coupling.h), which the elastic
// law solves once per scene for each coupled order: a 20 mm shaft and its 30 mm hub over 40 mm of
// 0.5 mm rows (paper-case1-h7js6's coupling rows) and over longer parts of the same rows, for the
// breathing mode and for an order past it. The elements' cost in docs/performance.md comes from here:
//   build/bench/fitfeel_surface_cylindrical_benchmark --benchmark_filter=AxialElements
#include <vector>

#include <benchmark/benchmark.h>

#include "surfaces/cylindrical/elastic/axial_coupling.h"

namespace fitfeel::cylindrical {
namespace {

void BM_AxialElements(benchmark::State& state) {
  const int rows = static_cast<int>(state.range(0));
  const int order = static_cast<int>(state.range(1));
  const bool hub = state.range(2) != 0;
  AxialBody body;
  body.inner_radius = hub ? 0.010 : 0.0;
  body.outer_radius = hub ? 0.015 : 0.010;
  body.loaded_inside = hub;
  body.material = {"steel", 210e9, 0.3};
  std::vector<double> edges(static_cast<std::size_t>(rows) + 1);
  for (int i = 0; i <= rows; ++i) edges[static_cast<std::size_t>(i)] = 0.5e-3 * i;
  for (auto _ : state) {
    const AxialCoupling part(body, edges, order);
    benchmark::DoNotOptimize(part.matrix().data());
  }
  state.SetLabel(hub ? "hub" : "shaft");
}
BENCHMARK(BM_AxialElements)
    ->ArgsProduct({{40, 80, 400}, {0, 3}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fitfeel::cylindrical
