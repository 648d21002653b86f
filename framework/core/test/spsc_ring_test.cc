#include "framework/core/spsc_ring.h"

#include <cstdint>
#include <thread>

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

struct Record {
  std::uint64_t index;
  double value;
};

TEST(SpscRing, RoundsCapacityUpAndRefusesNonsense) {
  EXPECT_EQ(SpscRing<Record>(5).capacity(), 8u);
  EXPECT_EQ(SpscRing<Record>(8).capacity(), 8u);
  EXPECT_THROW(SpscRing<Record>(0), UserError);
  EXPECT_THROW(SpscRing<Record>((std::size_t{1} << 30) + 1), UserError);
}

TEST(SpscRing, FullRingRefusesAndKeepsOrder) {
  SpscRing<Record> ring(4);
  for (std::uint64_t i = 0; i < 4; ++i) EXPECT_TRUE(ring.TryPush({i, 0.5 * i}));
  EXPECT_FALSE(ring.TryPush({99, 0.0}));  // full: dropped, not overwritten
  EXPECT_EQ(ring.size(), 4u);
  Record r{};
  for (std::uint64_t i = 0; i < 4; ++i) {
    ASSERT_TRUE(ring.TryPop(&r));
    EXPECT_EQ(r.index, i);
  }
  EXPECT_FALSE(ring.TryPop(&r));
  EXPECT_TRUE(ring.TryPush({7, 0.0}));  // space again after popping, across the wrap
  ASSERT_TRUE(ring.PopLatest(&r));
  EXPECT_EQ(r.index, 7u);
  EXPECT_FALSE(ring.PopLatest(&r));
}

TEST(SpscRing, PopLatestKeepsTheNewest) {
  SpscRing<Record> ring(16);
  for (std::uint64_t i = 0; i < 10; ++i) ASSERT_TRUE(ring.TryPush({i, 0.0}));
  Record r{};
  ASSERT_TRUE(ring.PopLatest(&r));
  EXPECT_EQ(r.index, 9u);
  EXPECT_EQ(ring.size(), 0u);
}

// A producer and a consumer on two threads: every record the producer managed to push arrives
// once, in order, intact; the producer never waits.
TEST(SpscRing, TwoThreadsLoseNothingThatWasPushed) {
  SpscRing<Record> ring(64);
  constexpr std::uint64_t kRecords = 200000;
  std::uint64_t pushed = 0;
  std::thread producer([&] {
    for (std::uint64_t i = 0; i < kRecords; ++i) {
      if (ring.TryPush({pushed, static_cast<double>(pushed) * 2.0})) ++pushed;
    }
  });
  std::uint64_t expected = 0;
  bool ok = true;
  std::thread consumer([&] {
    Record r{};
    auto drain = [&] {
      while (ring.TryPop(&r)) {
        ok = ok && r.index == expected && r.value == static_cast<double>(expected) * 2.0;
        ++expected;
      }
    };
    for (int spin = 0; spin < 2000000 && expected < kRecords; ++spin) drain();
  });
  producer.join();
  consumer.join();
  Record r{};
  while (ring.TryPop(&r)) {
    ok = ok && r.index == expected;
    ++expected;
  }
  EXPECT_TRUE(ok);
  EXPECT_EQ(expected, pushed);
  EXPECT_GT(pushed, 0u);
}

}  // namespace
}  // namespace fitfeel
