#pragma once

// What the scene benchmarks share (header-only: each benchmark is its own executable): the clocks
// they time a tick with, the plugins and the shipped scenarios.
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <benchmark/benchmark.h>

#include "framework/plugin/registry.h"
#include "framework/scenario/sequence.h"

namespace fitfeel::bench {

inline double ClockSeconds(clockid_t clock) {
  timespec ts{};
  clock_gettime(clock, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Median cost of reading the thread CPU clock, s (a system call on most kernels): taken off each
// timed tick.
inline double ClockCost() {
  std::vector<double> d(2001);
  for (double& x : d) {
    const double a = ClockSeconds(CLOCK_THREAD_CPUTIME_ID);
    const double b = ClockSeconds(CLOCK_THREAD_CPUTIME_ID);
    x = b - a;
  }
  std::nth_element(d.begin(), d.begin() + 1000, d.end());
  return d[1000];
}

// The plugins, loaded once per process from the default search path.
inline const PluginRegistry& Registry() {
  static const PluginRegistry* registry = [] {
    auto* r = new PluginRegistry();
    r->LoadAll();
    return r;
  }();
  return *registry;
}

// The shipped scenarios: FITFEEL_SOURCE_DIR's, else the current folder's (`make bench` runs from
// the source tree).
inline std::filesystem::path ScenarioDir() {
  if (const char* source = std::getenv("FITFEEL_SOURCE_DIR")) {
    return std::filesystem::path(source) / "scenarios";
  }
  return "scenarios";
}

// The shipped scenes' files in name order (a sequence's steps are scenes of their own, timed
// where they run); empty, with a line on stderr naming `program`, when there are none.
inline std::vector<std::filesystem::path> ShippedSceneFiles(const char* program) {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path folder = ScenarioDir();
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end;
       it.increment(error)) {
    if (it->path().extension() == ".yaml" && !IsSequenceFile(it->path())) {
      files.push_back(it->path());
    }
  }
  if (error || files.empty()) {
    std::fprintf(stderr,
                 "%s: no scenario files (*.yaml) in '%s'%s%s; run it from the repository's root "
                 "or set FITFEEL_SOURCE_DIR to it\n",
                 program, folder.string().c_str(), error ? ": " : "",
                 error ? error.message().c_str() : "");
    return {};
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Registers `run` (a callable taking benchmark::State&) as benchmark `name`: one whole run per
// iteration, five repetitions, their aggregates only, in milliseconds.
template <class Run>
void RegisterWholeRuns(const std::string& name, Run run) {
  benchmark::RegisterBenchmark(name.c_str(), run)
      ->Iterations(1)
      ->Repetitions(5)
      ->ReportAggregatesOnly(true)
      ->Unit(benchmark::kMillisecond);
}

// A benchmark's main: `body`, whose exception becomes a line on stderr naming `program` and exit
// code 2.
inline int MainOf(const char* program, int argc, char** argv, int (*body)(int, char**)) {
  try {
    return body(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", program, e.what());
    return 2;
  }
}

// Google Benchmark's run of the registered benchmarks with `reporter`: 1 for an argument it does
// not know, else 0.
inline int RunRegistered(int argc, char** argv, benchmark::BenchmarkReporter* reporter) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks(reporter);
  benchmark::Shutdown();
  return 0;
}

}  // namespace fitfeel::bench
