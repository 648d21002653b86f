#pragma once

// Counting the heap allocations of a tick path in a test, header-only. The test binary replaces
// the global operator new once, at global scope in one of its translation units:
//
//   FITFEEL_COUNT_ALLOCATIONS();
//
// and a test counts what a stretch of code allocates:
//
//   FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
//   fitfeel::test_support::ScopedAllocationCounter counter;
//   ... the tick ...
//   counter.Stop();
//   EXPECT_EQ(counter.count(), 0);
//
// The replacement is global, so a binary that uses it counts every operator new in every thread
// while a counter is armed; ctest runs each test in a process of its own, so one test's threads
// never count in another's. In this tree every such test is in fitfeel_allocation_test, whose
// replacement is framework/testing/count_allocations.cc (fitfeel_add_allocation_test). Memory
// Eigen or C code takes with malloc is not seen (operator new is the C++ heap entry point this
// counts).

#include <atomic>
#include <cassert>
#include <cstddef>
#include <cstdlib>
#include <new>

// AddressSanitizer brings its own allocator, with which a replaced operator new (or an interposed
// malloc) clashes: sanitizer builds do not count, and the counting tests skip saying so
// (FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS); the Release suite runs them.
#if defined(__SANITIZE_ADDRESS__)
#define FITFEEL_ALLOCATION_COUNTING 0
#else
#define FITFEEL_ALLOCATION_COUNTING 1
#endif

// In a test body, before counting: skips the test where allocations are not counted, and fails it
// where the binary does not replace operator new (a counter that sees nothing would pass any
// tick).
#define FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS()                                              \
  if (!FITFEEL_ALLOCATION_COUNTING)                                                            \
    GTEST_SKIP() << "allocations are not counted under AddressSanitizer (its allocator "        \
                    "replaces the one the counter hooks); the Release suite counts them";       \
  else if (!::fitfeel::test_support::OperatorNewIsCounted())                                   \
  FAIL() << "this binary does not count operator new: expand FITFEEL_COUNT_ALLOCATIONS() once, " \
            "at global scope in one of its files"

// Not fitfeel::testing: inside namespace fitfeel that name would hide GoogleTest's ::testing.
namespace fitfeel::test_support {

// The process-wide tally the replaced operator new feeds while armed.
struct AllocationTally {
  static inline std::atomic<bool> armed{false};
  static inline std::atomic<long> count{0};
};

// Counts every operator new from construction until Stop() or destruction. One at a time.
class ScopedAllocationCounter {
 public:
  ScopedAllocationCounter() {
    assert(!AllocationTally::armed.load() && "allocation counters do not nest");
    AllocationTally::count = 0;
    AllocationTally::armed = true;
  }
  ~ScopedAllocationCounter() { Stop(); }
  ScopedAllocationCounter(const ScopedAllocationCounter&) = delete;
  ScopedAllocationCounter& operator=(const ScopedAllocationCounter&) = delete;

  // Stops counting; count() keeps what was seen until then.
  void Stop() { AllocationTally::armed = false; }

  // Allocations seen so far (still growing until Stop()).
  long count() const { return AllocationTally::count.load(); }
};

// Whether this binary's operator new feeds the tally: one allocation under a counter. Through
// a volatile pointer, so that the compiler cannot leave the allocation out.
inline bool OperatorNewIsCounted() {
  ScopedAllocationCounter probe;
  void* volatile block = ::operator new(1);
  ::operator delete(block);
  probe.Stop();
  return probe.count() > 0;
}

}  // namespace fitfeel::test_support

// Replaces the global operator new and delete of the test binary so that ScopedAllocationCounter
// sees every allocation; expand once per test binary, at global scope (a second expansion is a
// link error). operator new[] and the nothrow forms reach this operator new through the standard
// library's defaults.
// GCC 12 reports the free() in the replaced operator delete as mismatched with `new` once both are
// inlined, although the replaced operator new allocates with malloc: a false positive.
// Not clang-formatted: it would run the _Pragma lines together.
// clang-format off
#if FITFEEL_ALLOCATION_COUNTING
#define FITFEEL_COUNT_ALLOCATIONS()                                                            \
  _Pragma("GCC diagnostic push")                                                              \
  _Pragma("GCC diagnostic ignored \"-Wmismatched-new-delete\"")                               \
  void* operator new(std::size_t size) {                                                      \
    if (::fitfeel::test_support::AllocationTally::armed.load(std::memory_order_relaxed)) {    \
      ::fitfeel::test_support::AllocationTally::count.fetch_add(1);                           \
    }                                                                                         \
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;                                \
    throw std::bad_alloc();                                                                   \
  }                                                                                           \
  void operator delete(void* p) noexcept { std::free(p); }                                    \
  void operator delete(void* p, std::size_t) noexcept { std::free(p); }                       \
  _Pragma("GCC diagnostic pop")                                                               \
  static_assert(true, "")
#else
#define FITFEEL_COUNT_ALLOCATIONS() static_assert(true, "")
#endif
// clang-format on
