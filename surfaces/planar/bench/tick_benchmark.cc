// Per-tick cost of the planar contact analyzer and law, and the prepare cost, on the key scene's
// grids (DIN 6885 8 x 7 x 40 key in a 45 mm JS9 hub keyway) and on a finer grid.
#include <benchmark/benchmark.h>

#include "framework/testing/tick_benchmark.h"
#include "surfaces/planar/planar_contact_analyzer.h"
#include "surfaces/planar/planar_generator.h"
#include "surfaces/planar/planar_discretizer.h"
#include "surfaces/planar/planar_law.h"
#include "surfaces/planar/test/test_support.h"

namespace fitfeel::planar {
namespace {

struct Scene {
  PartSpec key = testing::MakePart("key", Role::kInner, 8e-3, -36e-6, 0.0, 40e-3, 2.6e-3);
  PartSpec slot = testing::MakePart("slot", Role::kOuter, 8e-3, -18e-6, 18e-6, 45e-3, 2.6e-3);
  SkinModelShape k, s;
  ModelSettings settings;
  explicit Scene(Resolution res) {
    key.form.tolerance[FormCharacteristic::kFlatness] = 12e-6;
    slot.form.tolerance[FormCharacteristic::kFlatness] = 12e-6;
    settings.friction = 0.15;
    settings.contact_stiffness = 2.278e9;
    Rng rng(2);
    k = PlanarVariationGenerator().Generate(key, PlanarDiscretizer().Discretize(key, res),
                                            TextureMode::kExpected, rng);
    s = PlanarVariationGenerator().Generate(slot, PlanarDiscretizer().Discretize(slot, res),
                                            TextureMode::kExpected, rng);
  }
};

Resolution Grid(const benchmark::State& state) {
  if (state.range(0) == 0) return Resolution{};
  return Resolution{static_cast<int>(state.range(0)), static_cast<int>(state.range(1))};
}

void BM_PlanarTick(benchmark::State& state) {
  Scene scene(Grid(state));
  PlanarContactAnalyzer analyzer;
  analyzer.Prepare(scene.key, scene.k, scene.slot, scene.s, scene.settings);
  PlanarGpsLaw law;
  law.Prepare(scene.key, scene.slot, scene.settings);
  MatingMotion motion;
  motion.velocity.y() = 0.01;
  test_support::TimeTicks(state, analyzer, law, motion, [depth = 0.0]() mutable {
    MatingPose pose;
    pose.depth = depth;
    pose.offset = {1e-6, 0.0};
    depth += 1e-5;
    if (depth > 80e-3) depth = 0.0;
    return pose;
  });
}
BENCHMARK(BM_PlanarTick)->Args({0, 0})->Args({160, 48});

void BM_PlanarPrepare(benchmark::State& state) {
  Scene scene(Grid(state));
  for (auto _ : state) {
    PlanarContactAnalyzer analyzer;
    analyzer.Prepare(scene.key, scene.k, scene.slot, scene.s, scene.settings);
    benchmark::DoNotOptimize(analyzer);
  }
}
BENCHMARK(BM_PlanarPrepare)->Args({0, 0})->Args({160, 48})->Unit(benchmark::kMillisecond);

void BM_PlanarGenerate(benchmark::State& state) {
  Scene scene(Grid(state));
  const SurfaceGrid grid = PlanarDiscretizer().Discretize(scene.key, Grid(state));
  Rng rng(1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        PlanarVariationGenerator().Generate(scene.key, grid, TextureMode::kExpected, rng));
  }
}
BENCHMARK(BM_PlanarGenerate)->Args({0, 0})->Args({160, 48})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace fitfeel::planar
