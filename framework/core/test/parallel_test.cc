#include "framework/core/parallel.h"

#include <atomic>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

// Every item once, whatever the thread count (more threads than items, too).
TEST(ParallelForEach, CallsEveryItemOnce) {
  for (int threads : {1, 2, 3, 8}) {
    for (int count : {0, 1, 5, 40}) {
      std::vector<std::atomic<int>> calls(static_cast<std::size_t>(count));
      ParallelForEach(count, [&](int item) { ++calls[static_cast<std::size_t>(item)]; }, threads);
      for (int i = 0; i < count; ++i) {
        EXPECT_EQ(calls[static_cast<std::size_t>(i)].load(), 1)
            << "item " << i << " of " << count << ", " << threads << " threads";
      }
    }
  }
}

// An item's exception reaches the caller, and the items no thread had taken are not started.
TEST(ParallelForEach, RethrowsAndTakesNoMore) {
  for (int threads : {1, 2}) {
    std::atomic<int> started{0};
    EXPECT_THROW(ParallelForEach(
                     1000,
                     [&](int item) {
                       ++started;
                       if (item == 3) throw std::runtime_error("item 3");
                     },
                     threads),
                 std::runtime_error);
    EXPECT_LT(started.load(), 1000) << threads << " threads";
  }
}

}  // namespace
}  // namespace fitfeel
