// The elastic model's accuracy against its cost over the circumferential orders coupled along the
// parts' axes (model.options.axial_orders): each iteration prepares the six 3-D CalculiX cases
// (surfaces/cylindrical/test/solid_cases.h) and reports, beside the time, each case's error
// against the FEM and the largest (percent). The setting's table in docs/validation.md is this:
//   build/bench/fitfeel_surface_cylindrical_benchmark --benchmark_filter=CoupledOrders
#include <cmath>
#include <string>

#include <benchmark/benchmark.h>

#include "surfaces/cylindrical/test/solid_cases.h"

namespace fitfeel::cylindrical {
namespace {

using namespace testing;

void BM_CoupledOrders(benchmark::State& state) {
  const std::string options = "{axial_orders: " + std::to_string(state.range(0)) + "}";
  std::vector<SolidCase> cases;
  for (const std::string& name : SolidCaseNames()) cases.emplace_back(name);
  std::vector<double> error(cases.size());
  for (auto _ : state) {
    for (std::size_t k = 0; k < cases.size(); ++k) {
      error[k] = 100.0 * (SolidCaseElasticForce(cases[k], options) / cases[k].fem_force - 1.0);
    }
  }
  double largest = 0.0;
  for (std::size_t k = 0; k < cases.size(); ++k) {
    state.counters[cases[k].name] = error[k];
    largest = std::max(largest, std::abs(error[k]));
  }
  state.counters["largest_error_pct"] = largest;
}
BENCHMARK(BM_CoupledOrders)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Arg(3)
    ->Arg(4)
    ->Arg(6)
    ->Arg(8)
    ->Arg(12)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
}  // namespace fitfeel::cylindrical
