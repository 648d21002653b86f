#pragma once

#include <functional>

#include "framework/core/export.h"

namespace fitfeel {

// Threads that prepare-time loops split their work over: FITFEEL_PREPARE_THREADS if set to a
// positive integer, else the hardware's concurrency (at least 1). Never used in the tick.
FITFEEL_API int PrepareThreads();

// While it lives, PrepareThreads() gives `threads` on the thread that made it (and only there): a
// study whose pairs keep every core busy prepares each pair on the pair's own thread. What a
// prepare computes never depends on its thread count.
class FITFEEL_API ScopedPrepareThreads {
 public:
  explicit ScopedPrepareThreads(int threads);
  ~ScopedPrepareThreads();
  ScopedPrepareThreads(const ScopedPrepareThreads&) = delete;
  ScopedPrepareThreads& operator=(const ScopedPrepareThreads&) = delete;

 private:
  int outer_;
};

// Calls body(begin, end) on `threads` contiguous, disjoint chunks of [0, count) (the calling
// thread takes the first), and returns when all are done; rethrows the first chunk's exception.
// The split never changes what a chunk computes, so work whose items are independent gives the
// same result bit for bit whatever the thread count.
FITFEEL_API void ParallelFor(int count, const std::function<void(int begin, int end)>& body,
                             int threads = PrepareThreads());

// Calls body(i) for every i in [0, count) on `threads` threads that each take the next item no
// thread has taken yet: for a few items of uneven cost, where contiguous chunks would leave one
// thread with the expensive ones. Returns when all are done; rethrows a failed item's exception
// (items not yet taken then are skipped). An item that writes only its own results gives the
// same result whichever thread took it.
FITFEEL_API void ParallelForEach(int count, const std::function<void(int item)>& body,
                                 int threads = PrepareThreads());

}  // namespace fitfeel
