// Cost of the joint stage's tick (framework/runtime/joint_stage.h, docs/assemblies.md) in the
// shipped scenes that join two features: each one prepared once, then run whole in virtual time
// (the simulated device, the scheduler with its safety chain), one run per benchmark iteration,
// each with a fresh scheduler and so fresh run states. Unlike scene_benchmark, which prepares
// the scene again for every run and runs every scenario, it gives many runs of the joints alone
// in the time of a few, for the tick's upper percentiles and for profiling
// (`perf record build/bench/joint_tick_benchmark`).
//
// Counters: tick_p50_us, tick_p99_us, tick_max_us over every tick of every run, thread CPU time
// of each Scheduler::Tick less the clock's own cost (CPU time, not wall time: the development
// machine is shared); evaluations_p50, _p99, _max, the contact evaluations per tick (every
// feature's analyzer counts), the same in every run and on every machine. "/hand" drives the scene
// with the simulated hand 1 mm off the axis (framework/testing/hand_scene.h) instead of its robot.
//
// Scenarios come from $FITFEEL_SOURCE_DIR/scenarios, else ./scenarios (run it from the
// repository's root): build/bench/joint_tick_benchmark [--benchmark_filter=keyed-hub]
#include <time.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "framework/plugin/registry.h"
#include "framework/runtime/bench/bench_support.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/scene_stages.h"
#include "framework/runtime/scheduler.h"
#include "framework/scenario/scene.h"
#include "framework/testing/hand_scene.h"
#include "framework/testing/virtual_scene_run.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

using bench::ClockCost;
using bench::Registry;

double ThreadSeconds() { return bench::ClockSeconds(CLOCK_THREAD_CPUTIME_ID); }

// The scene loaded from its file's text (with the hand in place of its device where asked).
Scene Load(const std::string& name, bool hand) {
  const fs::path file = bench::ScenarioDir() / (name + ".yaml");
  if (!hand) return LoadScene(file, Registry());
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const fs::path temporary =
      fs::temp_directory_path() / ("fitfeel-joint-bench-hand-" + name + ".yaml");
  std::ofstream(temporary) << test_support::WithHand(text, 1e-3, test_support::kHandPushIn, 3.5);
  Scene scene = LoadScene(temporary, Registry());
  fs::remove(temporary);
  return scene;
}

double Percentile(std::vector<double>* v, double q) {
  if (v->empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v->size() - 1));
  std::nth_element(v->begin(), v->begin() + static_cast<std::ptrdiff_t>(k), v->end());
  return (*v)[k];
}

void BM_JointRun(benchmark::State& state, const std::string& name, bool hand) {
  static const double clock_cost = ClockCost();
  Scene scene = Load(name, hand);
  const PreparedScene prepared = Prepare(scene);
  std::vector<double> ticks;
  Percentiles evaluations;
  for (auto _ : state) {
    test_support::VirtualSceneRun run(scene, prepared);
    Scheduler& scheduler = run.scheduler();
    ticks.reserve(ticks.size() + scheduler.planned_ticks());
    for (std::uint64_t k = 0; k < scheduler.planned_ticks(); ++k) {
      const double t0 = ThreadSeconds();
      const bool more = scheduler.Tick(static_cast<double>(k) / run.rate());
      ticks.push_back(std::max(0.0, ThreadSeconds() - t0 - clock_cost) * 1e6);
      if (!more) break;
    }
    evaluations = scheduler.StatsSoFar().contact_evaluations;
  }
  state.counters["tick_p50_us"] = Percentile(&ticks, 0.50);
  state.counters["tick_p99_us"] = Percentile(&ticks, 0.99);
  state.counters["tick_max_us"] = *std::max_element(ticks.begin(), ticks.end());
  state.counters["evaluations_p50"] = evaluations.p50;
  state.counters["evaluations_p99"] = evaluations.p99;
  state.counters["evaluations_max"] = evaluations.max;
}

// One benchmark per scene and device, named after the scenario ("BM_JointRun/keyed-hub/hand").
const bool kRegistered = [] {
  for (const char* name : {"keyed-hub", "two-pin-location"}) {
    for (const bool hand : {false, true}) {
      // The shorter two-pin-location (1.3 s) runs twice as often for as many ticks.
      const int runs = std::string(name) == "two-pin-location" && !hand ? 40 : 20;
      benchmark::RegisterBenchmark(
          ("BM_JointRun/" + std::string(name) + (hand ? "/hand" : "")).c_str(),
          [name, hand](benchmark::State& state) { BM_JointRun(state, name, hand); })
          ->Iterations(runs)
          ->Unit(benchmark::kMillisecond);
    }
  }
  return true;
}();

}  // namespace
}  // namespace fitfeel
