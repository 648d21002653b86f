// Cost of one tick (analyzer Evaluate + law Evaluate) of the taper pin at the auto resolution
// (20 x 72 pin cells for the 40 mm pin) and at finer grids: the tick is one pass over the pin's
// cells, so it grows linearly with m x n.
#include <benchmark/benchmark.h>

#include "framework/testing/tick_benchmark.h"
#include "surfaces/conical/conical_contact_analyzer.h"
#include "surfaces/conical/conical_discretizer.h"
#include "surfaces/conical/conical_generator.h"
#include "surfaces/conical/conical_law.h"
#include "surfaces/conical/test/test_parts.h"

namespace fitfeel::conical {
namespace {

void BM_ConicalTick(benchmark::State& state) {
  PartSpec pin = test::Pin();
  PartSpec hole = test::Hole();
  pin.size.lower_deviation = -58e-6;
  hole.size.upper_deviation = 58e-6;
  pin.form.tolerance[FormCharacteristic::kRoundness] = 6e-6;
  hole.form.tolerance[FormCharacteristic::kGeneratrixStraightness] = 15e-6;
  const Resolution r = test_support::BenchmarkGrid(state);
  ModelSettings settings;
  settings.friction = 0.15;
  settings.contact_stiffness = 1e6;
  ConicalContactAnalyzer analyzer;
  TaperPressFitLaw law;
  test_support::PreparePair<ConicalDiscretizer, ConicalVariationGenerator>(pin, hole, r, settings,
                                                                           &analyzer, &law);
  MatingMotion motion;
  motion.velocity.y() = 0.01;
  test_support::TimeTicks(state, analyzer, law, motion, [depth = 20e-3]() mutable {
    MatingPose pose;
    pose.depth = depth;
    depth += 1e-8;
    return pose;
  });
  state.counters["cells"] = static_cast<double>(r.rows) * r.columns;
}
BENCHMARK(BM_ConicalTick)->Args({20, 72})->Args({40, 360})->Args({200, 360});

}  // namespace
}  // namespace fitfeel::conical
