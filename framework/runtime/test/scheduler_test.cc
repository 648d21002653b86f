#include "framework/runtime/scheduler.h"

#include <cmath>
#include <random>

#include "framework/core/error.h"
#include "framework/runtime/constrained_stage.h"
#include "framework/runtime/outputs.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/test/fake_scene.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

// A constrained stage whose response depends on a draw made from the scene's generator when it
// is prepared: a stiffness-like gain times the depth plus a ripple of drawn phase.
class RngStage final : public Stage {
 public:
  explicit RngStage(Rng& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    gain_ = 100.0 + 100.0 * u(rng);
    phase_ = 2.0 * M_PI * u(rng);
  }
  StageId DoId() const override { return StageId::kConstrained; }

 protected:
  void DoEvaluate(const PartState& d, StageState*, StageOutput* out) const noexcept override {
    out->pose = MatingPoseOf(d);
    out->wrench.SetZero();
    out->wrench.force.y() = -gain_ * out->pose.depth * (1.0 + 0.1 * std::sin(phase_ + d.time));
    out->next = out->pose.depth < 0.0 ? StageId::kPositioning : StageId::kConstrained;
  }

 private:
  double gain_ = 0.0, phase_ = 0.0;
};

// The trace without the measured compute time: what must be bit-for-bit reproducible.
std::vector<std::string> PhysicsRows(const std::vector<TickRecord>& trace) {
  std::vector<std::string> rows;
  for (auto r : trace) {
    r.compute_us = 0.0;
    rows.push_back(TraceRow(r));
  }
  return rows;
}

std::vector<std::string> RunWithSeed(std::uint64_t seed) {
  const Scene scene = testing::MakeFakeScene(seed);
  PreparedScene prepared = Prepare(scene);
  const PositioningStage positioning;
  const RngStage constrained(prepared.rng);
  scene.device->Start(1e-3);
  Scheduler scheduler(*scene.device, positioning, constrained, {1000.0, 0.5, ClockMode::kVirtual});
  scheduler.Run();
  return PhysicsRows(scheduler.trace());
}

TEST(SchedulerTest, VirtualClockRunsExactlyDurationTimesRateTicks) {
  testing::KinematicDevice device(-1e-3, 10e-3);
  const PreparedScene prepared = Prepare(testing::MakeFakeScene(1));
  const PositioningStage positioning;
  const ConstrainedStage constrained(*prepared.analyzer, *prepared.law);
  device.Start(1.0 / 2000.0);
  Scheduler scheduler(device, positioning, constrained, {2000.0, 1.2345, ClockMode::kVirtual});
  EXPECT_EQ(scheduler.planned_ticks(), 2469u);  // round(1.2345 * 2000)
  scheduler.Run();
  EXPECT_EQ(scheduler.stats().ticks, 2469u);
  EXPECT_EQ(scheduler.trace().size(), 2469u);
  EXPECT_EQ(device.writes(), 2469);
  EXPECT_EQ(scheduler.ticks_done(), 2469u);
  for (std::size_t k = 0; k < scheduler.trace().size(); ++k) {
    ASSERT_EQ(scheduler.trace()[k].time, static_cast<double>(k) / 2000.0);
  }
  EXPECT_FALSE(scheduler.stats().realtime);
  EXPECT_EQ(scheduler.stats().deadline_misses, 0u);
  EXPECT_GT(scheduler.stats().compute_us.max, 0.0);
  EXPECT_LE(scheduler.stats().compute_us.p50, scheduler.stats().compute_us.p99);
  EXPECT_LE(scheduler.stats().compute_us.p99, scheduler.stats().compute_us.max);
}

TEST(SchedulerTest, HandsOverAtTheEntranceAndBack) {
  const PreparedScene prepared = Prepare(testing::MakeFakeScene(1));
  const PositioningStage positioning;
  const ConstrainedStage constrained(*prepared.analyzer, *prepared.law);
  // From 1 mm before the entrance at 10 mm/s: the leading end reaches it at t = 0.1 s (tick 100);
  // the positioning stage sees depth >= 0 there and the constrained stage runs from tick 101.
  testing::KinematicDevice device(-1e-3, 10e-3);
  device.Start(1e-3);
  Scheduler scheduler(device, positioning, constrained, {1000.0, 0.3, ClockMode::kVirtual});
  scheduler.Run();
  const auto& trace = scheduler.trace();
  EXPECT_EQ(trace[100].stage, StageId::kPositioning);
  EXPECT_GE(trace[100].pose.depth, 0.0);
  EXPECT_EQ(trace[101].stage, StageId::kConstrained);
  EXPECT_LT(trace[99].pose.depth, 0.0);
  EXPECT_EQ(trace[299].stage, StageId::kConstrained);

  // Withdrawing: moving backwards from inside, the constrained stage hands back.
  testing::KinematicDevice back(1e-3, -10e-3);
  back.Start(1e-3);
  Scheduler reverse(back, positioning, constrained, {1000.0, 0.3, ClockMode::kVirtual});
  reverse.Run();
  EXPECT_EQ(reverse.trace()[0].stage, StageId::kPositioning);
  EXPECT_EQ(reverse.trace()[1].stage, StageId::kConstrained);
  EXPECT_EQ(reverse.trace()[299].stage, StageId::kPositioning);
}

TEST(SchedulerTest, HandsTheContactStiffnessToTheDeviceOnlyInContact) {
  const PreparedScene prepared = Prepare(testing::MakeFakeScene(1));
  const auto& analyzer = static_cast<const testing::FakeAnalyzer&>(*prepared.analyzer);
  const PositioningStage positioning;
  const ConstrainedStage constrained(*prepared.analyzer, *prepared.law);
  SchedulerSettings settings{1000.0, 0.2, ClockMode::kVirtual};
  // Inside the clearance: never in contact.
  testing::KinematicDevice free(-1e-3, 10e-3, {0.0, 0.5 * analyzer.clearance()});
  free.Start(1e-3);
  Scheduler a(free, positioning, constrained, settings);
  a.Run();
  EXPECT_EQ(free.stiffness(), 0.0);
  // Beyond it once engaged.
  testing::KinematicDevice pressed(-1e-3, 10e-3, {0.0, -(analyzer.clearance() + 1e-6)});
  pressed.Start(1e-3);
  Scheduler b(pressed, positioning, constrained, settings);
  b.Run();
  // The fake law's radial spring is k_p = 1e5 N/m.
  EXPECT_NEAR(pressed.stiffness(), 1e5, 1e-3);
}

TEST(SchedulerTest, SameSeedGivesIdenticalTracesAnotherSeedDoesNot) {
  const auto a = RunWithSeed(7);
  const auto b = RunWithSeed(7);
  const auto c = RunWithSeed(8);
  ASSERT_EQ(a.size(), 500u);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  // They differ where the drawn stage acts, not before the entrance.
  EXPECT_EQ(a[50], c[50]);
}

TEST(SchedulerTest, GuardReplacesNonFiniteWrenchesByZeroAndCountsThem) {
  const Scene scene =
      testing::MakeFakeScene(1, 0.5, nullptr, std::make_shared<testing::FakeSurface>(true));
  const PreparedScene prepared = Prepare(scene);
  const PositioningStage positioning;
  const ConstrainedStage constrained(*prepared.analyzer, *prepared.law);
  // The fake law returns a NaN axial force once engaged by more than 5 mm: from t = 0.1 s on.
  testing::KinematicDevice deep(4e-3, 10e-3);
  deep.Start(1e-3);
  Scheduler faulty(deep, positioning, constrained, {1000.0, 0.5, ClockMode::kVirtual});
  faulty.Run();
  std::uint64_t faults = 0;
  for (const auto& r : faulty.trace()) {
    EXPECT_TRUE(r.wrench.AllFinite());
    if (r.guard_fault) {
      ++faults;
      EXPECT_EQ(r.wrench.force, Eigen::Vector3d::Zero());
    }
  }
  EXPECT_GT(faults, 300u);
  EXPECT_EQ(faults, faulty.stats().guard_faults);
  EXPECT_TRUE(deep.last().AllFinite());
}

class FiniteDevice final : public Device {
 public:
  explicit FiniteDevice(int ticks) : left_(ticks) {}
  DeviceSpec DoSpec() const override { return testing::UnlimitedSpec(); }
  bool DoActive() const override { return left_ > 0; }

 protected:
  void DoConfigure(const ConfigNode&) override {}
  void DoStart(double) override {}
  void DoRead(double, DeviceState* out) noexcept override { out->position.y() = -1.0; }
  void DoWrite(const Wrench&) noexcept override { --left_; }

 private:
  int left_;
};

TEST(SchedulerTest, StopsWhenTheDeviceBecomesInactive) {
  FiniteDevice device(123);
  const PositioningStage positioning;
  const RngStage constrained(*std::make_unique<Rng>(1));
  Scheduler scheduler(device, positioning, constrained, {1000.0, 1.0, ClockMode::kVirtual});
  scheduler.Run();
  EXPECT_EQ(scheduler.stats().ticks, 123u);
  EXPECT_EQ(scheduler.stats().planned_ticks, 1000u);
}

// A device whose own "servo thread" calls the tick (here synchronously, at its native 500 Hz).
class HalfRateServoDevice final : public Device {
 public:
  DeviceSpec DoSpec() const override { return testing::UnlimitedSpec(); }
  ClockOwner DoClockOwner() const override { return ClockOwner::kDevice; }
  void DoRunServoLoop(double duration, const std::function<bool(double)>& tick) override {
    for (int k = 0; k * 2e-3 < duration; ++k) {
      if (!tick(k * 2e-3)) break;
      ++calls;
    }
  }
  int calls = 0;

 protected:
  void DoConfigure(const ConfigNode&) override {}
  void DoStart(double) override {}
  void DoRead(double t, DeviceState* out) noexcept override { out->position.y() = t - 0.1; }
  void DoWrite(const Wrench&) noexcept override {}
};

TEST(SchedulerTest, DeviceOwnedClockCallsTheSameTick) {
  HalfRateServoDevice device;
  const PositioningStage positioning;
  Rng rng(1);
  const RngStage constrained(rng);
  Scheduler scheduler(device, positioning, constrained, {500.0, 0.4, ClockMode::kVirtual});
  scheduler.Run();
  EXPECT_EQ(device.calls, 200);
  EXPECT_EQ(scheduler.stats().ticks, 200u);
  EXPECT_TRUE(scheduler.stats().realtime);
  EXPECT_EQ(scheduler.trace().back().stage, StageId::kConstrained);
}

TEST(SchedulerTest, RefusesImpossibleSettings) {
  testing::KinematicDevice device(0.0, 0.0);
  const PositioningStage positioning;
  Rng rng(1);
  const RngStage constrained(rng);
  EXPECT_THROW(Scheduler(device, positioning, constrained, {0.0, 1.0, ClockMode::kVirtual}),
               UserError);
  EXPECT_THROW(Scheduler(device, positioning, constrained, {1000.0, -1.0, ClockMode::kVirtual}),
               UserError);
  EXPECT_THROW(Scheduler(device, positioning, constrained, {1000.0, 1e-5, ClockMode::kVirtual}),
               UserError);
  EXPECT_THROW(Scheduler(device, positioning, constrained, {1000.0, 1e9, ClockMode::kVirtual}),
               UserError);
  EXPECT_THROW(Scheduler(device, constrained, positioning, {1000.0, 1.0, ClockMode::kVirtual}),
               UserError);
}

TEST(PercentilesTest, NearestRank) {
  std::vector<double> v;
  for (int i = 1; i <= 200; ++i) v.push_back(201 - i);
  const Percentiles p = ComputePercentiles(v);
  EXPECT_EQ(p.p50, 100.0);
  EXPECT_EQ(p.p99, 198.0);
  EXPECT_EQ(p.max, 200.0);
  EXPECT_EQ(ComputePercentiles({}).max, 0.0);
  EXPECT_EQ(ComputePercentiles({5.0}).p99, 5.0);
}

}  // namespace
}  // namespace fitfeel
