#pragma once

// What the scene benchmarks share (header-only: each benchmark is its own executable): the clocks
// they time a tick with, the plugins and the shipped scenarios.
#include <time.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "framework/plugin/registry.h"

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

}  // namespace fitfeel::bench
