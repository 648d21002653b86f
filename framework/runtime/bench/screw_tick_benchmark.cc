// Cost of the screw stage's tick (framework/runtime/screw_stage.h, docs/threads.md) on
// scenarios/bolt-m10.yaml, by phase: the nut's run-down along the bolt (its flanks' play, the
// wrench's light push), its tightening from the face met to the torque target (preload built
// against the bearing face), and the nut held at its angle once there. The scene is prepared
// once; each benchmark iteration runs its ScrewStage alone, tick by tick at the scene's rate over
// the scene's duration, from a fresh run state handed over at the nut's entrance, with no device
// or safety chain around it: the stage's own cost. Each benchmark times the ticks of its phase
// only.
//
// Counters: ticks, the phase's ticks per run; tick_p50_us, tick_p99_us, tick_max_us over them in
// every run, thread CPU time of each ScrewStage::Evaluate less the clock's own cost (CPU time, not
// wall time: the development machine is shared); evaluations_p50, _p99, _max, the contact
// evaluations per tick, the same in every run and on every machine.
//
// Scenarios come from $FITFEEL_SOURCE_DIR/scenarios, else ./scenarios (run it from the
// repository's root): build/bench/screw_tick_benchmark [--benchmark_filter=tightening]
#include <time.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "framework/runtime/bench/bench_support.h"
#include "framework/runtime/part_state.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/scene_stages.h"
#include "framework/runtime/stage.h"
#include "framework/scenario/scene.h"

namespace fitfeel {
namespace {

enum class Phase { kRunDown, kTightening, kHeld };

double ThreadSeconds() { return bench::ClockSeconds(CLOCK_THREAD_CPUTIME_ID); }

double Percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// bolt-m10 prepared once for every benchmark of the process, its screw stage built for the
// scene's device as `fitfeel run` builds it.
struct PreparedScrew {
  Scene scene;
  PreparedScene prepared;
  SceneStages stages;
};

const PreparedScrew& BoltM10() {
  static const PreparedScrew* screw = [] {
    auto* s = new PreparedScrew{
        LoadScene(bench::ScenarioDir() / "bolt-m10.yaml", bench::Registry()), {}, {}};
    s->prepared = Prepare(s->scene);
    // Started first: a device knows its limits only at its rate.
    s->scene.device->Start(1.0 / s->scene.run.rate);
    s->stages = MakeSceneStages(s->scene, s->prepared, s->scene.device->spec());
    s->scene.device->Stop();
    return s;
  }();
  return *screw;
}

// Which phase a tick was in: the screw's state before it (a tick that meets the face or reaches
// the torque belongs to the phase it ends).
Phase PhaseOf(const ScrewOutput& before) {
  if (before.stopped) return Phase::kHeld;
  return before.seated ? Phase::kTightening : Phase::kRunDown;
}

void BM_ScrewTick(benchmark::State& state, Phase phase) {
  static const double clock_cost = bench::ClockCost();
  const PreparedScrew& screw = BoltM10();
  const Stage& stage = *screw.stages.constrained;
  const double rate = screw.scene.run.rate;
  const auto ticks_per_run = static_cast<std::int64_t>(screw.scene.run.duration * rate);
  std::vector<double> ticks, evaluations;
  std::int64_t phase_ticks = 0;
  for (auto _ : state) {
    const std::unique_ptr<StageState> run = stage.MakeState();
    // Handed over at the nut's entrance, as the positioning stage hands it over.
    StageOutput out;
    out.stage = StageId::kPositioning;
    phase_ticks = 0;
    for (std::int64_t k = 0; k < ticks_per_run; ++k) {
      PartState part;
      part.time = static_cast<double>(k) / rate;
      const Phase now = k == 0 ? Phase::kRunDown : PhaseOf(out.screw);
      const double t0 = ThreadSeconds();
      stage.Evaluate(part, run.get(), &out);
      const double seconds = ThreadSeconds() - t0;
      if (now != phase) continue;
      ++phase_ticks;
      ticks.push_back(std::max(0.0, seconds - clock_cost) * 1e6);
      evaluations.push_back(out.contact_evaluations);
    }
  }
  if (ticks.empty()) {
    state.SkipWithError("bolt-m10 never reached this phase");
    return;
  }
  state.counters["ticks"] = static_cast<double>(phase_ticks);
  state.counters["tick_p50_us"] = Percentile(ticks, 0.50);
  state.counters["tick_p99_us"] = Percentile(ticks, 0.99);
  state.counters["tick_max_us"] = *std::max_element(ticks.begin(), ticks.end());
  state.counters["evaluations_p50"] = Percentile(evaluations, 0.50);
  state.counters["evaluations_p99"] = Percentile(evaluations, 0.99);
  state.counters["evaluations_max"] = *std::max_element(evaluations.begin(), evaluations.end());
}

// Every iteration is a whole run of six seconds (6000 ticks): the tightening's 70 ticks a run
// need more runs for a p99 than the run-down's 5000.
const bool kRegistered = [] {
  struct Entry {
    const char* name;
    Phase phase;
    int runs;
  };
  for (const Entry& e :
       {Entry{"rundown", Phase::kRunDown, 10}, Entry{"tightening", Phase::kTightening, 100},
        Entry{"held", Phase::kHeld, 10}}) {
    benchmark::RegisterBenchmark(
        ("BM_ScrewTick/bolt-m10/" + std::string(e.name)).c_str(),
        [phase = e.phase](benchmark::State& state) { BM_ScrewTick(state, phase); })
        ->Iterations(e.runs)
        ->Unit(benchmark::kMillisecond);
  }
  return true;
}();

}  // namespace
}  // namespace fitfeel
