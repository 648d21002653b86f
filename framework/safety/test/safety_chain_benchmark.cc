#include <cmath>

#include <benchmark/benchmark.h>

#include "framework/device/device_specs.h"
#include "framework/safety/safety_chain.h"

namespace fitfeel {
namespace {

void BM_SafetyChainApply(benchmark::State& state) {
  SafetySettings s;
  s.coupling = state.range(0) ? CouplingMode::kSpringDamper : CouplingMode::kDirect;
  s.force_scale = 0.01;
  s.passivity_controller = true;
  SafetyChain chain;
  chain.Configure(s, LookupDeviceSpec("PHANTOM Desktop"), 1e-3);
  PartState device;
  Wrench physical;
  long k = 0;
  for (auto _ : state) {
    device.position.y() = 0.001 * std::sin(static_cast<double>(k) * 0.01);
    PartState law;
    chain.SimulatedState(device, &law);
    physical.force.y() = 2e6 * std::max(0.0, -law.position.y());
    benchmark::DoNotOptimize(chain.Apply(physical, device, 1e-3));
    ++k;
  }
}
BENCHMARK(BM_SafetyChainApply)->Arg(0)->Arg(1);

}  // namespace
}  // namespace fitfeel
