// Every shipped scenario as a whole scene in virtual time: what `fitfeel run` does (prepare, both
// stages, the simulated device, the scheduler with its safety chain and record), timed in CPU
// time because the development machine is shared: a tick's wall time there includes other jobs'
// time slices, its thread CPU time does not.
//
// One benchmark iteration is one whole run of a scenario (a fresh scene, prepare, every tick).
// Counters: prepare_ms, CPU time of the process during Prepare (all threads: a parallel prepare
// counts both cores' work); prepare_wall_ms, its wall time (what a user waits for, on this
// shared machine also other jobs' time slices); tick_p50_us, tick_p99_us, tick_max_us, thread
// CPU time of each Scheduler::Tick, less the clock's own cost (measured once, the median of
// back-to-back reads); evaluations_p50, _p99, _max, the contact analyzer's evaluations per tick
// (the run's statistics: the same on every machine, where the times are this one's).
// Repetitions give the median of each counter. Scenes whose surface keeps its per-tick scan
// (conical, spherical) run again with the scan analyzer in place of the tables ("/scan"), for
// the ratio.
//
// After Google Benchmark's own output, a Markdown table of the medians, one row per scenario, with
// the scan's p50 / p99 and the ratio where a scan exists: docs/performance.md's scene table.
//
// Scenes with a lead-in run once more with the simulated hand 1 mm off the axis pushing the part
// in ("/hand": the god object's cost; framework/testing/hand_scene.h).
//
// Scenarios come from $FITFEEL_SOURCE_DIR/scenarios, else ./scenarios (`make bench` runs from the
// repository's root). Run: build/bench/scene_benchmark [--benchmark_filter=taper]
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "framework/core/error.h"
#include "framework/plugin/registry.h"
#include "framework/runtime/bench/bench_support.h"
#include "framework/runtime/constrained_stage.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/scene_stages.h"
#include "framework/runtime/scheduler.h"
#include "framework/scenario/scene.h"
#include "framework/testing/hand_scene.h"
#include "framework/testing/virtual_scene_run.h"
#include "surfaces/conical/conical_scan_analyzer.h"
#include "surfaces/spherical/spherical_scan_analyzer.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

using bench::ClockCost;
using bench::ClockSeconds;
using bench::Registry;

// The surface plugin's per-tick scan, prepared on the scene's shapes; null where none exists.
std::unique_ptr<ContactAnalyzer> ScanAnalyzer(const Scene& scene, const PreparedScene& prepared) {
  std::unique_ptr<ContactAnalyzer> scan;
  if (scene.surface_id == "fitfeel.surface.conical") {
    scan = std::make_unique<conical::ConicalScanAnalyzer>();
  } else if (scene.surface_id == "fitfeel.surface.spherical") {
    scan = std::make_unique<spherical::SphericalScanAnalyzer>();
  } else {
    return nullptr;
  }
  scan->Prepare(scene.inner, *prepared.inner_sms, scene.outer, *prepared.outer_sms, scene.model);
  return scan;
}

bool HasScan(const std::string& surface_id) {
  return surface_id == "fitfeel.surface.conical" || surface_id == "fitfeel.surface.spherical";
}

double Percentile(std::vector<double>* v, double q) {
  if (v->empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(v->size() - 1));
  std::nth_element(v->begin(), v->begin() + static_cast<std::ptrdiff_t>(k), v->end());
  return (*v)[k];
}

// The scenario with the simulated hand 1 mm off the axis pushing its part in (the god object's
// cost, docs/lead-in.md), written to a temporary file of its own.
fs::path HandVariant(const fs::path& file) {
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const fs::path out =
      fs::temp_directory_path() /
      ("fitfeel-bench-hand-" + std::to_string(::getpid()) + "-" + file.filename().string());
  std::ofstream(out) << test_support::WithHand(text, 1e-3, test_support::kHandPushIn, 3.5);
  return out;
}

// True where the hand variant means something: a surface with a lead-in.
bool HasLeadIn(const fs::path& file) {
  const Scene scene = LoadScene(file, Registry());
  return !scene.surface->MakeLeadIn(scene.inner, scene.outer).empty();
}

void BM_Scene(benchmark::State& state, const fs::path& file, bool scan) {
  static const double clock_cost = ClockCost();
  std::vector<double> ticks;
  for (auto _ : state) {
    Scene scene = LoadScene(file, Registry());
    const double cpu0 = ClockSeconds(CLOCK_PROCESS_CPUTIME_ID);
    const double wall0 = ClockSeconds(CLOCK_MONOTONIC);
    PreparedScene prepared = Prepare(scene);
    const double prepare = ClockSeconds(CLOCK_PROCESS_CPUTIME_ID) - cpu0;
    const double prepare_wall = ClockSeconds(CLOCK_MONOTONIC) - wall0;
    if (scan) prepared.analyzer = ScanAnalyzer(scene, prepared);
    test_support::VirtualSceneRun run(scene, prepared);
    Scheduler& scheduler = run.scheduler();
    ticks.assign(scheduler.planned_ticks(), 0.0);
    std::size_t done = 0;
    for (; done < ticks.size(); ++done) {
      const double t0 = ClockSeconds(CLOCK_THREAD_CPUTIME_ID);
      const bool more = scheduler.Tick(static_cast<double>(done) / run.rate());
      const double t1 = ClockSeconds(CLOCK_THREAD_CPUTIME_ID);
      ticks[done] = std::max(0.0, t1 - t0 - clock_cost) * 1e6;
      if (!more) break;
    }
    const Percentiles evaluations = scheduler.StatsSoFar().contact_evaluations;
    state.counters["evaluations_p50"] = evaluations.p50;
    state.counters["evaluations_p99"] = evaluations.p99;
    state.counters["evaluations_max"] = evaluations.max;
    ticks.resize(std::min(done + 1, ticks.size()));
    state.counters["prepare_ms"] = prepare * 1e3;
    state.counters["prepare_wall_ms"] = prepare_wall * 1e3;
    state.counters["tick_max_us"] = *std::max_element(ticks.begin(), ticks.end());
    state.counters["tick_p99_us"] = Percentile(&ticks, 0.99);
    state.counters["tick_p50_us"] = Percentile(&ticks, 0.50);
    state.counters["ticks"] = static_cast<double>(ticks.size());
  }
}

// Google Benchmark's console output, then the medians as one Markdown table.
class TableReporter final : public benchmark::ConsoleReporter {
 public:
  TableReporter() : ConsoleReporter(OO_Tabular) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& run : runs) {
      if (run.aggregate_name != "median") continue;
      std::string name = run.run_name.function_name;  // scene/<name>[/scan|/hand]
      name = name.substr(name.find('/') + 1);
      const bool scan = name.size() > 5 && name.substr(name.size() - 5) == "/scan";
      if (scan) name.resize(name.size() - 5);
      const bool hand = name.size() > 5 && name.substr(name.size() - 5) == "/hand";
      if (hand) name = name.substr(0, name.size() - 5) + ", hand 1 mm off";
      Row& row = rows_[name];
      Medians& m = scan ? row.scan : row.table;
      m.present = true;
      m.prepare_ms = Counter(run, "prepare_ms");
      m.prepare_wall_ms = Counter(run, "prepare_wall_ms");
      m.p50 = Counter(run, "tick_p50_us");
      m.p99 = Counter(run, "tick_p99_us");
      m.max = Counter(run, "tick_max_us");
      m.evaluations_p50 = Counter(run, "evaluations_p50");
      m.evaluations_p99 = Counter(run, "evaluations_p99");
      m.evaluations_max = Counter(run, "evaluations_max");
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf(
        "\n| scenario | prepare (ms CPU) | prepare (ms wall) | tick p50 / p99 / max (us CPU) | "
        "contact evaluations p50 / p99 / max | per-tick scan p50 / p99 (us CPU) | scan / table "
        "p99 |\n"
        "|---|---|---|---|---|---|---|\n");
    for (const auto& [name, row] : rows_) {
      std::printf("| `%s` | %.1f | %.1f | %.2f / %.2f / %.0f | %.0f / %.0f / %.0f |", name.c_str(),
                  row.table.prepare_ms, row.table.prepare_wall_ms, row.table.p50, row.table.p99,
                  row.table.max, row.table.evaluations_p50, row.table.evaluations_p99,
                  row.table.evaluations_max);
      if (row.scan.present) {
        std::printf(" %.1f / %.0f | %.0f |\n", row.scan.p50, row.scan.p99,
                    row.scan.p99 / row.table.p99);
      } else {
        std::printf(" - | - |\n");
      }
    }
    std::fflush(stdout);
  }

 private:
  struct Medians {
    bool present = false;
    double prepare_ms = 0.0, prepare_wall_ms = 0.0, p50 = 0.0, p99 = 0.0, max = 0.0;
    double evaluations_p50 = 0.0, evaluations_p99 = 0.0, evaluations_max = 0.0;
  };
  struct Row {
    Medians table, scan;
  };
  static double Counter(const Run& run, const std::string& name) {
    const auto it = run.counters.find(name);
    return it == run.counters.end() ? 0.0 : static_cast<double>(it->second);
  }
  std::map<std::string, Row> rows_;
};

}  // namespace
}  // namespace fitfeel

// Registers a benchmark per scene (and its scan and hand variants) and runs them. Throws what a
// scene that does not load, or a missing plugin, throws.
static int RunScenes(int argc, char** argv) {
  using namespace fitfeel;
  const std::vector<fs::path> files = bench::ShippedSceneFiles("scene_benchmark");
  if (files.empty()) return 2;
  for (const fs::path& file : files) {
    const std::string name = file.stem().string();
    for (bool scan : {false, true}) {
      if (scan && !HasScan(LoadScene(file, Registry()).surface_id)) continue;
      bench::RegisterWholeRuns("scene/" + name + (scan ? "/scan" : ""),
                               [file, scan](benchmark::State& s) { BM_Scene(s, file, scan); });
    }
    if (HasLeadIn(file)) {
      const fs::path hand = HandVariant(file);
      bench::RegisterWholeRuns("scene/" + name + "/hand",
                               [hand](benchmark::State& s) { BM_Scene(s, hand, false); });
    }
  }
  TableReporter reporter;
  return bench::RunRegistered(argc, argv, &reporter);
}

int main(int argc, char** argv) {
  return fitfeel::bench::MainOf("scene_benchmark", argc, argv, RunScenes);
}
