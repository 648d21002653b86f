// Prepare-time cost of skin model shape generation (discretise + generate with every form check)
// for grids from the automatic paper grid up to 10^6 cells.
#include <benchmark/benchmark.h>

#include "surfaces/cylindrical/cylindrical_discretizer.h"
#include "surfaces/cylindrical/cylindrical_generator.h"
#include "surfaces/cylindrical/test/test_parts.h"

namespace fitfeel::cylindrical {
namespace {

void BM_GeneratePaperShaft(benchmark::State& state) {
  const PartSpec part = testing::PaperShaft();
  const Resolution resolution{static_cast<int>(state.range(0)), static_cast<int>(state.range(1))};
  const SurfaceGrid grid = CylindricalDiscretizer().Discretize(part, resolution);
  const CylindricalVariationGenerator generator;
  std::uint64_t seed = 1;
  double regenerations = 0.0;
  for (auto _ : state) {
    Rng rng(seed++);
    const SkinModelShape sms = generator.Generate(part, grid, TextureMode::kSampled, rng);
    regenerations += sms.regenerations;
    benchmark::DoNotOptimize(sms.variation.data());
  }
  state.counters["cells"] = grid.size();
  state.counters["regenerations"] = regenerations / state.iterations();
}
BENCHMARK(BM_GeneratePaperShaft)
    ->Args({48, 48})
    ->Args({100, 96})
    ->Args({240, 360})
    ->Args({500, 200})
    ->Args({1000, 1000})
    ->Unit(benchmark::kMillisecond);

void BM_GenerateWithCylindricity(benchmark::State& state) {
  PartSpec part = testing::PaperShaft();
  part.form.tolerance[FormCharacteristic::kCylindricity] = 12e-6;
  part.form.tolerance[FormCharacteristic::kGeneratrixStraightness] = 6e-6;
  const Resolution resolution{static_cast<int>(state.range(0)), static_cast<int>(state.range(1))};
  const SurfaceGrid grid = CylindricalDiscretizer().Discretize(part, resolution);
  const CylindricalVariationGenerator generator;
  std::uint64_t seed = 1;
  double regenerations = 0.0;
  for (auto _ : state) {
    Rng rng(seed++);
    const SkinModelShape sms = generator.Generate(part, grid, TextureMode::kSampled, rng);
    regenerations += sms.regenerations;
    benchmark::DoNotOptimize(sms.variation.data());
  }
  state.counters["cells"] = grid.size();
  state.counters["regenerations"] = regenerations / state.iterations();
}
BENCHMARK(BM_GenerateWithCylindricity)
    ->Args({48, 48})
    ->Args({100, 96})
    ->Args({240, 360})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fitfeel::cylindrical
