
#include <chrono>
#include <cmath>
#include <thread>

#include "framework/runtime/constrained_stage.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/scheduler.h"
#include "framework/runtime/test/fake_scene.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

// Two seconds on the real clock. Timing on a shared machine is reported, not asserted: the test checks
// that every tick ran, that the statistics are filled in and consistent, and what absolute
// deadlines guarantee whatever the load (the run cannot be shorter than its schedule).
TEST(RealTimeSchedulerTest, TwoSecondsAtOneKilohertz) {
  const PreparedScene prepared = Prepare(testing::MakeFakeScene(1));
  const PositioningStage positioning;
  const ConstrainedStage constrained(*prepared.analyzer, *prepared.law);
  testing::KinematicDevice device(-1e-3, 10e-3);
  device.Start(1e-3);
  Scheduler scheduler(device, positioning, constrained, {1000.0, 2.0, ClockMode::kRealTime});
  scheduler.Run();
  const RunStats& s = scheduler.stats();
  EXPECT_TRUE(s.realtime);
  EXPECT_EQ(s.ticks, 2000u);
  EXPECT_FALSE(s.realtime_note.empty());
  // The rate a loaded machine achieves is reported below, not asserted; absolute deadlines
  // cannot run ahead of the clock, so 2000 ticks take (nearly: the last starts at 1.999 s) 2 s.
  EXPECT_GT(s.achieved_rate, 0.0);
  EXPECT_GE(s.wall_seconds, 1.99);
  EXPECT_LE(s.jitter_us.p50, s.jitter_us.p99);
  EXPECT_LE(s.jitter_us.p99, s.jitter_us.max);
  EXPECT_LE(s.lateness_us.p50, s.lateness_us.max);
  EXPECT_GE(s.lateness_us.p50, 0.0);  // nobody wakes before an absolute deadline
  EXPECT_LE(s.deadline_misses, s.ticks);
  // Scheduled times are the nominal ones, whatever the wake-ups were.
  EXPECT_EQ(scheduler.trace()[1500].time, 1.5);
  std::printf(
      "real time 2 s: %s\n  compute us p50/p99/max %.2f/%.2f/%.2f, period jitter us "
      "p50/p99/max %.1f/%.1f/%.1f, wake lateness us p50/p99/max %.1f/%.1f/%.1f, "
      "misses %llu, rate %.1f Hz\n",
      s.realtime_note.c_str(), s.compute_us.p50, s.compute_us.p99, s.compute_us.max,
      s.jitter_us.p50, s.jitter_us.p99, s.jitter_us.max, s.lateness_us.p50, s.lateness_us.p99,
      s.lateness_us.max, static_cast<unsigned long long>(s.deadline_misses), s.achieved_rate);
}

TEST(OverrunGuard, ZeroOnAMissedDeadlineThenARampBack) {
  OverrunGuard guard;
  const double period = 1e-3;
  EXPECT_EQ(guard.Factor(0.2e-3, period), 1.0);  // late within its period: on time
  EXPECT_EQ(guard.Factor(1.5e-3, period), 0.0);  // woke after the next deadline: zero
  for (int k = 1; k <= OverrunGuard::kRampTicks; ++k) {
    EXPECT_DOUBLE_EQ(guard.Factor(0.0, period), static_cast<double>(k) / OverrunGuard::kRampTicks);
  }
  EXPECT_EQ(guard.Factor(0.0, period), 1.0);
  EXPECT_EQ(guard.Factor(2e-3, period), 0.0);  // a second overrun restarts the ramp
  EXPECT_EQ(guard.overruns(), 2u);
}

// A stage that renders a constant force and, once, computes for 3 ms: an injected overrun.
class SlowOnceStage final : public Stage {
 public:
  StageId DoId() const override { return StageId::kPositioning; }

 protected:
  void DoEvaluate(const PartState& device, StageState*, StageOutput* out) const noexcept override {
    out->wrench.SetZero();
    out->wrench.force.y() = -1.0;
    out->next = StageId::kPositioning;
    if (device.time >= 0.2 && device.time < 0.2005) {
      std::this_thread::sleep_for(std::chrono::milliseconds(3));
    }
  }
};

// Real time with an injected overrun: the late tick sends zero, the next ones ramp back, and the
// summary counts it. Every check holds under any schedule: a sleep only ever lasts longer, so the
// tick after the slow one wakes at least 2 ms late, and another miss anywhere only restarts the
// ramp, which keeps the force below the bound checked.
TEST(RealTimeSchedulerTest, AnInjectedOverrunSendsZeroThenRampsBack) {
  const PreparedScene prepared = Prepare(testing::MakeFakeScene(1));
  const SlowOnceStage slow;
  const ConstrainedStage constrained(*prepared.analyzer, *prepared.law);
  testing::KinematicDevice device(-1e-3, 0.0);
  device.Start(1e-3);
  Scheduler scheduler(device, slow, constrained, {1000.0, 0.4, ClockMode::kRealTime});
  scheduler.Run();
  EXPECT_GE(scheduler.stats().overruns, 1u);
  const auto& trace = scheduler.trace();
  // The tick after the slow one woke at least 2 ms late.
  EXPECT_EQ(trace[201].wrench.force.y(), -1.0);
  EXPECT_EQ(trace[201].device_wrench.force.y(), 0.0);
  // Within the next 20 ticks the device force never exceeds the ramp's.
  for (int k = 1; k <= OverrunGuard::kRampTicks; ++k) {
    EXPECT_LE(std::abs(trace[201 + k].device_wrench.force.y()),
              static_cast<double>(k) / OverrunGuard::kRampTicks + 1e-12)
        << k;
  }
}

}  // namespace
}  // namespace fitfeel
