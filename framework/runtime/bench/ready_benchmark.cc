// How soon every shipped scene is ready to touch, and how fast its progressive prepare's frontier
// then runs ahead of a hand (docs/progressive-prepare.md).
//
// One benchmark iteration prepares a scenario as `fitfeel run` does (PrepareProgressive, with the
// run's reach) and then its rest step by step on the same thread, as the worker would. Counters,
// in CPU time of the process (the development machine is shared: wall time there includes other
// jobs' time slices); run it on one core (taskset -c 0, FITFEEL_PREPARE_THREADS=1) for the figure
// the issue asks for:
//   ready_ms     until PrepareProgressive returned: the scene is ready to touch;
//   whole_ms     until every table was whole;
//   frontier_mm_per_s  the datum analyzer's frontier speed over its rest (depth gained per CPU
//                second; 0 where it prepares whole);
//   lead_mm      the least distance the frontier kept ahead of a hand that enters at 10 mm/s
//                the moment the scene is ready (the frontier before each step against where the
//                hand is when that step is done); positive: that hand is never held.
// Repetitions give the median of each counter; after Google Benchmark's own output, a Markdown
// table of the medians (docs/progressive-prepare.md's table).
//
// Scenarios come from $FITFEEL_SOURCE_DIR/scenarios, else ./scenarios. Run:
//   FITFEEL_PREPARE_THREADS=1 taskset -c 0 build/bench/ready_benchmark
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "framework/runtime/bench/bench_support.h"
#include "framework/runtime/prepare.h"
#include "framework/scenario/scene.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

using bench::ClockSeconds;
using bench::Registry;

constexpr double kHandSpeed = 10e-3;  // m/s: the hand

double ProcessSeconds() { return ClockSeconds(CLOCK_PROCESS_CPUTIME_ID); }

void BM_Ready(benchmark::State& state, const fs::path& file) {
  for (auto _ : state) {
    Scene scene = LoadScene(file, Registry());
    ProgressiveSettings settings;
    settings.worker = false;
    const double t0 = ProcessSeconds();
    PreparedScene prepared =
        PrepareProgressive(scene, settings, nullptr, scene.device->reach(scene.run.duration),
                           scene.device->angular_reach(scene.run.duration));
    const double ready = ProcessSeconds();
    // The rest as the worker does it, one step at a time, the datum analyzer's frontier timed.
    double lead = std::numeric_limits<double>::infinity(), covered = 0.0, datum_seconds = 0.0;
    ContactAnalyzer& datum = *prepared.analyzer;
    double frontier = datum.prepared_depth();
    const double start_frontier = frontier;
    while (datum.PrepareAhead(1)) {
      const double now = ProcessSeconds() - ready;
      lead = std::min(lead, frontier - kHandSpeed * now);
      frontier = datum.prepared_depth();
      covered = frontier - start_frontier;
      datum_seconds = now;
    }
    prepared.FinishPreparing();
    const double whole = ProcessSeconds();
    state.counters["ready_ms"] = (ready - t0) * 1e3;
    state.counters["whole_ms"] = (whole - t0) * 1e3;
    state.counters["frontier_mm_per_s"] = datum_seconds > 0.0 ? covered / datum_seconds * 1e3 : 0.0;
    state.counters["lead_mm"] = std::isfinite(lead) ? lead * 1e3 : 0.0;
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
      std::string name = run.run_name.function_name;  // ready/<name>
      name = name.substr(name.find('/') + 1);
      Row& row = rows_[name];
      for (const char* counter : {"ready_ms", "whole_ms", "frontier_mm_per_s", "lead_mm"}) {
        const auto it = run.counters.find(counter);
        row[counter] = it == run.counters.end() ? 0.0 : static_cast<double>(it->second);
      }
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf(
        "\n| scenario | ready to touch (ms CPU) | whole (ms CPU) | frontier (mm/s) | least lead "
        "over a 10 mm/s hand (mm) |\n|---|---|---|---|---|\n");
    for (auto& [name, row] : rows_) {
      std::printf("| `%s` | %.1f | %.1f | %.0f | %s |\n", name.c_str(), row["ready_ms"],
                  row["whole_ms"], row["frontier_mm_per_s"],
                  row["frontier_mm_per_s"] > 0.0
                      ? std::to_string(row["lead_mm"]).substr(0, 5).c_str()
                      : "whole");
    }
    std::fflush(stdout);
  }

 private:
  using Row = std::map<std::string, double>;
  std::map<std::string, Row> rows_;
};

}  // namespace
}  // namespace fitfeel

static int RunScenes(int argc, char** argv) {
  using namespace fitfeel;
  const std::vector<fs::path> files = bench::ShippedSceneFiles("ready_benchmark");
  if (files.empty()) return 2;
  for (const fs::path& file : files) {
    bench::RegisterWholeRuns("ready/" + file.stem().string(),
                             [file](benchmark::State& s) { BM_Ready(s, file); });
  }
  TableReporter reporter;
  return bench::RunRegistered(argc, argv, &reporter);
}

int main(int argc, char** argv) {
  return fitfeel::bench::MainOf("ready_benchmark", argc, argv, RunScenes);
}
