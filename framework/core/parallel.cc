#include "framework/core/parallel.h"

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <exception>
#include <thread>
#include <vector>

namespace fitfeel {

namespace {
thread_local int scoped_threads = 0;  // 0: none set on this thread
}  // namespace

ScopedPrepareThreads::ScopedPrepareThreads(int threads) : outer_(scoped_threads) {
  scoped_threads = std::max(1, threads);
}

ScopedPrepareThreads::~ScopedPrepareThreads() { scoped_threads = outer_; }

int PrepareThreads() {
  if (scoped_threads > 0) return scoped_threads;
  if (const char* text = std::getenv("FITFEEL_PREPARE_THREADS")) {
    char* end = nullptr;
    const long n = std::strtol(text, &end, 10);
    if (end != text && *end == '\0' && n > 0) return static_cast<int>(std::min(n, 256L));
  }
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void ParallelFor(int count, const std::function<void(int begin, int end)>& body, int threads) {
  if (count <= 0) return;
  threads = std::clamp(threads, 1, count);
  if (threads == 1) {
    body(0, count);
    return;
  }
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(threads));
  auto chunk = [&](int t) {
    const int begin = static_cast<int>(static_cast<long>(count) * t / threads);
    const int end = static_cast<int>(static_cast<long>(count) * (t + 1) / threads);
    try {
      body(begin, end);
    } catch (...) {
      errors[static_cast<std::size_t>(t)] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  workers.reserve(static_cast<std::size_t>(threads - 1));
  for (int t = 1; t < threads; ++t) workers.emplace_back(chunk, t);
  chunk(0);
  for (auto& w : workers) w.join();
  for (const auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

void ParallelForEach(int count, const std::function<void(int item)>& body, int threads) {
  std::atomic<int> next{0};
  ParallelFor(
      std::clamp(threads, 1, std::max(count, 1)),
      [&](int, int) {
        for (int item = next++; item < count; item = next++) {
          try {
            body(item);
          } catch (...) {
            next = count;  // the other threads take nothing more
            throw;
          }
        }
      },
      threads);
}

}  // namespace fitfeel
