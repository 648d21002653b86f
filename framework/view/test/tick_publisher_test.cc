#include "framework/view/tick_publisher.h"

#include <atomic>
#include <thread>

#include <gtest/gtest.h>

#include "framework/testing/allocation_counter.h"

namespace fitfeel::view {
namespace {

TickRecord Record(double depth) {
  TickRecord r;
  r.time = depth;
  r.pose.depth = depth;
  r.wrench.force = Eigen::Vector3d(1.0, -depth, 2.0);
  r.stage = StageId::kConstrained;
  r.contact.interference = true;
  return r;
}

TEST(TickPublisher, ReaderGetsTheNewestSample) {
  TickPublisher publisher(8);
  ViewSample s;
  EXPECT_FALSE(publisher.PopLatest(&s));
  for (int k = 0; k < 5; ++k) publisher.OnTick(Record(k));
  ASSERT_TRUE(publisher.PopLatest(&s));
  EXPECT_EQ(s.tick, 4u);
  EXPECT_EQ(s.depth, 4.0);
  EXPECT_EQ(s.force[1], -4.0);
  EXPECT_EQ(s.stage, 1);
  EXPECT_TRUE(s.interference);
  EXPECT_FALSE(publisher.PopLatest(&s));
  EXPECT_EQ(publisher.dropped(), 0u);
}

// The viewer draws the outer part fixed: where the outer part moves, a sample is the inner
// part's pose in the outer part's frame and the force on the inner part, the scene's reflected in
// z (AnalyzerPose); where the inner part moves, the scene's as it is.
TEST(TickPublisher, SamplesAreInTheOuterPartsFrame) {
  TickRecord r = Record(3.0);
  r.pose.offset = Eigen::Vector2d(1e-6, 2e-6);
  r.wrench.torque = Eigen::Vector3d(0.1, 0.2, 0.3);
  r.contact.offset_angle = 0.5;
  TickPublisher inner(8), outer(8, Role::kOuter);
  inner.OnTick(r);
  outer.OnTick(r);
  ViewSample a, b;
  ASSERT_TRUE(inner.PopLatest(&a));
  ASSERT_TRUE(outer.PopLatest(&b));
  EXPECT_EQ(a.offset_z, 2e-6);
  EXPECT_EQ(a.force[2], 2.0);
  EXPECT_EQ(b.depth, a.depth);
  EXPECT_EQ(b.offset_x, a.offset_x);
  EXPECT_EQ(b.offset_z, -2e-6);
  EXPECT_EQ(b.force[0], a.force[0]);
  EXPECT_EQ(b.force[1], a.force[1]);
  EXPECT_EQ(b.force[2], -2.0);
  EXPECT_EQ(b.torque[2], -0.3);
  EXPECT_EQ(b.offset_angle, -0.5);
}

TEST(TickPublisher, AFullRingDropsAndCountsWithoutAllocating) {
  TickPublisher publisher(4);
  const TickRecord r = Record(1.0);
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  test_support::ScopedAllocationCounter counter;
  for (int k = 0; k < 10; ++k) publisher.OnTick(r);  // nobody reads: 6 have no room
  counter.Stop();
  EXPECT_EQ(counter.count(), 0);
  EXPECT_EQ(publisher.dropped(), 6u);
  ViewSample s;
  ASSERT_TRUE(publisher.PopLatest(&s));
  EXPECT_EQ(s.tick, 3u);  // the ring kept the first four; later ones were dropped
}

TEST(TickPublisher, AConcurrentReaderSeesIncreasingTicks) {
  TickPublisher publisher(16);
  std::atomic<bool> done{false};
  std::uint64_t last = 0;
  std::atomic<std::uint64_t> seen{0};
  bool ordered = true;
  std::thread reader([&] {
    ViewSample s;
    // One pop after the writer is done too: on a loaded machine the reader may first run then.
    for (bool last_round = false; !last_round;) {
      last_round = done.load();
      if (publisher.PopLatest(&s)) {
        ordered = ordered && (seen == 0 || s.tick > last);
        last = s.tick;
        ++seen;
      }
    }
  });
  // On a loaded machine the reader may not be scheduled before 200 000 ticks are published: the
  // ticks go on (still increasing) until it has read a few.
  for (int k = 0; k < 200000 || seen.load() < 10; ++k) publisher.OnTick(Record(k));
  done = true;
  reader.join();
  EXPECT_TRUE(ordered);
  EXPECT_GT(seen, 0u);
}

TEST(TickPublisher, HistoryIsHandedOverOnce) {
  TickPublisher publisher;
  EXPECT_FALSE(publisher.TakeHistory().has_value());
  publisher.OnRecord(Record(1.0), 0);
  publisher.OnRecord(Record(2.0), 1);
  publisher.OnRunEnd();
  auto history = publisher.TakeHistory();
  ASSERT_TRUE(history.has_value());
  ASSERT_EQ(history->size(), 2u);
  EXPECT_EQ((*history)[1].tick, 1u);
  EXPECT_EQ((*history)[1].depth, 2.0);
  EXPECT_FALSE(publisher.TakeHistory().has_value());
}

}  // namespace
}  // namespace fitfeel::view
