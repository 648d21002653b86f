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

// An item's exception reaches the caller. On one thread nothing after the failed item starts.
// With more threads, the items another thread took before the failure was recorded still run,
// however the threads were scheduled, so only what holds under any schedule is checked: no item
// starts twice, and the items up to the failed one (each taken before it) all ran.
TEST(ParallelForEach, RethrowsAndTakesNoMore) {
  std::vector<int> started;
  EXPECT_THROW(ParallelForEach(
                   1000,
                   [&](int item) {
                     started.push_back(item);
                     if (item == 3) throw std::runtime_error("item 3");
                   },
                   1),
               std::runtime_error);
  EXPECT_EQ(started, (std::vector<int>{0, 1, 2, 3}));

  std::vector<std::atomic<int>> calls(1000);
  try {
    ParallelForEach(
        1000,
        [&](int item) {
          ++calls[static_cast<std::size_t>(item)];
          if (item == 3) throw std::runtime_error("item 3");
        },
        2);
    ADD_FAILURE() << "item 3's exception did not reach the caller";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "item 3");
  }
  for (std::size_t i = 0; i <= 3; ++i) EXPECT_EQ(calls[i].load(), 1) << "item " << i;
  for (std::size_t i = 0; i < calls.size(); ++i) EXPECT_LE(calls[i].load(), 1) << "item " << i;
}

}  // namespace
}  // namespace fitfeel
