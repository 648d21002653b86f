// The scheduler's tick with the safety chain and the recording must not allocate: count every
// operator new while it ticks.
#include <cmath>
#include <limits>
#include <memory>

// Framework headers first: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include "framework/device/device_specs.h"
#include "framework/runtime/scheduler.h"
#include "framework/testing/allocation_counter.h"

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

// Pushes into a wall at y = 0 and back out, with a sideways tremor.
class PushingDevice final : public Device {
 public:
  explicit PushingDevice(DeviceSpec spec) : spec_(std::move(spec)) {}
  DeviceSpec DoSpec() const override { return spec_; }

 protected:
  void DoConfigure(const ConfigNode&) override {}
  void DoStart(double) override {}
  void DoRead(double time, DeviceState* out) noexcept override {
    out->time = time;
    out->position = Eigen::Vector3d(1e-4 * std::sin(50.0 * time), 2e-3 * std::sin(3.0 * time), 0.0);
    out->velocity = Eigen::Vector3d(5e-3 * std::cos(50.0 * time), 6e-3 * std::cos(3.0 * time), 0.0);
  }
  void DoWrite(const Wrench&) noexcept override {}

 private:
  DeviceSpec spec_;
};

class WallStage final : public Stage {
 public:
  explicit WallStage(StageId id) : id_(id) {}
  StageId DoId() const override { return id_; }

 protected:
  void DoEvaluate(const PartState& d, StageState*, StageOutput* out) const noexcept override {
    out->wrench.SetZero();
    const double depth = d.position.y();
    out->wrench.force.y() = depth > 0.0 ? -1e6 * depth : 0.0;
    out->stiffness = depth > 0.0 ? 1e6 : 0.0;
    out->next = id_ == StageId::kPositioning ? StageId::kConstrained : StageId::kPositioning;
  }

 private:
  StageId id_;
};

TEST(SchedulerTickAllocation, CounterSeesAllocations) {
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  test_support::ScopedAllocationCounter allocations;
  auto probe = std::make_unique<double>(1.0);
  allocations.Stop();
  EXPECT_EQ(allocations.count(), 1);
}

TEST(SchedulerTickAllocation, TickWithTheSafetyChainAndRecordingDoesNotAllocate) {
  for (CouplingMode mode : {CouplingMode::kDirect, CouplingMode::kSpringDamper}) {
    PushingDevice device(LookupDeviceSpec("PHANTOM Desktop"));
    device.Start(1e-3);
    const WallStage positioning(StageId::kPositioning);
    const WallStage constrained(StageId::kConstrained);
    SchedulerSettings settings{1000.0, 2.0, ClockMode::kVirtual};
    settings.safety.coupling = mode;
    settings.safety.force_scale = 0.01;
    settings.safety.passivity_controller = true;
    settings.record = true;
    Scheduler scheduler(device, positioning, constrained, settings);
    FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
    test_support::ScopedAllocationCounter allocations;
    int ticks = 0;
    for (int k = 0; k < 2000; ++k) ticks += scheduler.Tick(k * 1e-3) ? 1 : 0;
    const double pushed = scheduler.safety().report().max_physical_force;
    scheduler.Rewind();
    ticks += scheduler.Tick(0.0) ? 1 : 0;
    allocations.Stop();
    EXPECT_EQ(ticks, 2001);
    EXPECT_EQ(allocations.count(), 0) << (mode == CouplingMode::kDirect ? "direct" : "coupled");
    EXPECT_GT(pushed, 0.0);  // the wall was met: the chain did real work
  }
}

// Streaming: the tick copies its row into the ring; when the ring is full (nobody drains it here)
// it drops and counts the row. Neither allocates.
TEST(SchedulerTickAllocation, AStreamingTickDoesNotAllocateWhetherTheRingHasRoomOrNot) {
  PushingDevice device(LookupDeviceSpec("PHANTOM Desktop"));
  device.Start(1e-3);
  const WallStage positioning(StageId::kPositioning);
  const WallStage constrained(StageId::kConstrained);
  SpscRing<StreamRow> ring(512);
  SchedulerSettings settings{1000.0, 2.0, ClockMode::kVirtual};
  settings.record = true;
  settings.stream = &ring;
  Scheduler scheduler(device, positioning, constrained, settings);
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  test_support::ScopedAllocationCounter allocations;
  int ticks = 0;
  for (int k = 0; k < 2000; ++k) ticks += scheduler.Tick(k * 1e-3) ? 1 : 0;
  allocations.Stop();
  EXPECT_EQ(ticks, 2000);
  EXPECT_EQ(allocations.count(), 0);
  EXPECT_EQ(ring.size(), 512u);
}

}  // namespace
}  // namespace fitfeel
