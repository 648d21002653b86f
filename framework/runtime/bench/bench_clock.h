#pragma once

// The clocks the scene benchmarks time a tick with (header-only: each benchmark is its own
// executable).
#include <time.h>

#include <algorithm>
#include <vector>

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

}  // namespace fitfeel::bench
