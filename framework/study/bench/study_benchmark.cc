// Fit studies' throughput: pairs per second of `fitfeel study` (RunStudy, virtual time, no files)
// for the paper's case study (a transition fit: some pairs interfere) and an H7/n6 press fit
// (every pair does), on 1 and 2 threads, with the pairs sharing what their prepares compute from
// the scene alone and ("_unshared") each pair computing everything itself.
//
// One iteration is one whole study (its first pair makes what the others share), timed in wall
// time: pairs_per_s is what a user sees, on a shared machine also other jobs' time slices (the
// cpu_ms_per_pair counter, the process's CPU time per pair over all threads, is not).
//
// Scenarios come from $FITFEEL_SOURCE_DIR/scenarios, else ./scenarios (`make bench` runs from the
// repository's root). Run: build/bench/study_benchmark [--benchmark_filter=case1]
#include <time.h>

#include <string>

#include <benchmark/benchmark.h>

#include "framework/runtime/bench/bench_support.h"
#include "framework/study/study.h"

namespace fitfeel {
namespace {

void Study(benchmark::State& state, const std::string& scenario, int pairs, bool share) {
  study::StudySettings settings;
  settings.pairs = pairs;
  settings.threads = static_cast<int>(state.range(0));
  settings.share_prepare = share;
  const auto file = bench::ScenarioDir() / (scenario + ".yaml");
  double cpu = 0.0;
  int done = 0;
  for (auto _ : state) {
    const double start = bench::ClockSeconds(CLOCK_PROCESS_CPUTIME_ID);
    const study::StudyResult result = study::RunStudy(file, bench::Registry(), settings);
    cpu += bench::ClockSeconds(CLOCK_PROCESS_CPUTIME_ID) - start;
    done += static_cast<int>(result.pairs.size());
    benchmark::DoNotOptimize(result.pairs.data());
  }
  state.counters["pairs_per_s"] = benchmark::Counter(done, benchmark::Counter::kIsRate);
  state.counters["cpu_ms_per_pair"] = done > 0 ? 1e3 * cpu / done : 0.0;
}

// Enough pairs per study that the first pair's shared solve weighs as in a long study (a few per
// cent of the case study's 40 pairs) and a repetition takes a few seconds.
BENCHMARK_CAPTURE(Study, case1, std::string("paper-case1-h7js6"), 40, true)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(Study, case1_unshared, std::string("paper-case1-h7js6"), 40, false)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(Study, h7n6, std::string("fits-20mm-h7n6"), 8, true)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(2);
BENCHMARK_CAPTURE(Study, h7n6_unshared, std::string("fits-20mm-h7n6"), 8, false)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(2);

}  // namespace
}  // namespace fitfeel
