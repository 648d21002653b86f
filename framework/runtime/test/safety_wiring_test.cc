// The safety chain in the scheduler's tick: pass-through for a device without limits, scaling,
// saturation and the virtual coupling for a desktop device, and the device-stream recording.
#include <cmath>
#include <cstring>


#include "framework/core/error.h"
#include "framework/device/device_specs.h"
#include "framework/runtime/constrained_stage.h"
#include "framework/runtime/outputs.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/scheduler.h"
#include "framework/runtime/test/fake_scene.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

bool SameBits(const Wrench& a, const Wrench& b) {
  return std::memcmp(a.force.data(), b.force.data(), 3 * sizeof(double)) == 0 &&
         std::memcmp(a.torque.data(), b.torque.data(), 3 * sizeof(double)) == 0;
}

std::optional<SafetySection> Yaml(const std::string& text) {
  return ParseSafetySection(ConfigNode::Parse(text, "test", "safety"));
}

// The fake scene's part pressed radially past the clearance: a contact with force from entry on.
struct PressedRun {
  PreparedScene prepared = Prepare(testing::MakeFakeScene(1));
  PositioningStage positioning;
  ConstrainedStage constrained{*prepared.analyzer, *prepared.law};
  double clearance() const {
    return static_cast<const testing::FakeAnalyzer&>(*prepared.analyzer).clearance();
  }
};

TEST(SafetyWiringTest, RuntimeDefaultsAreDirectOnlyForADeviceWithoutLimits) {
  const DeviceSpec unlimited = testing::UnlimitedSpec();
  const DeviceSpec phantom = LookupDeviceSpec("PHANTOM Desktop");
  EXPECT_EQ(RuntimeSafetySettings(std::nullopt, unlimited).coupling, CouplingMode::kDirect);
  EXPECT_EQ(RuntimeSafetySettings(std::nullopt, phantom).coupling, CouplingMode::kSpringDamper);
  EXPECT_EQ(RuntimeSafetySettings(Yaml("{force_scale: 0.5}"), unlimited).coupling,
            CouplingMode::kDirect);
  EXPECT_EQ(RuntimeSafetySettings(Yaml("{force_scale: 0.5}"), unlimited).force_scale, 0.5);
  EXPECT_EQ(RuntimeSafetySettings(Yaml("{coupling: spring_damper}"), unlimited).coupling,
            CouplingMode::kSpringDamper);
  EXPECT_EQ(RuntimeSafetySettings(Yaml("{coupling: direct}"), phantom).coupling,
            CouplingMode::kDirect);
  EXPECT_THROW(Yaml("{coupling: magnetic}"), ScenarioError);
}

TEST(SafetyWiringTest, AnUnlimitedDeviceReceivesTheStageWrenchBitForBit) {
  PressedRun run;
  testing::KinematicDevice device(-1e-3, 10e-3, {0.0, -(run.clearance() + 1e-6)});
  device.Start(1e-3);
  SchedulerSettings settings{1000.0, 0.3, ClockMode::kVirtual};
  settings.safety = RuntimeSafetySettings(std::nullopt, device.spec());
  Scheduler scheduler(device, run.positioning, run.constrained, settings);
  scheduler.Run();
  int loaded = 0;
  for (const TickRecord& r : scheduler.trace()) {
    ASSERT_TRUE(SameBits(r.wrench, r.device_wrench)) << "t = " << r.time;
    if (r.wrench.force.norm() > 0.0) ++loaded;
    // The law saw the device itself.
    ASSERT_EQ(r.position.y(), -1e-3 + 10e-3 * r.time);
  }
  EXPECT_GT(loaded, 100);
  EXPECT_TRUE(SameBits(device.last(), scheduler.trace().back().device_wrench));
  // Directly, the device integrates the contact's own stiffness (the fake law's k_p = 1e5 N/m).
  EXPECT_NEAR(device.stiffness(), 1e5, 1e-3);
  const SafetyReport& safety = scheduler.stats().safety;
  EXPECT_EQ(safety.force_scale, 1.0);
  EXPECT_EQ(safety.coupling, CouplingMode::kDirect);
  EXPECT_EQ(safety.non_finite_faults, 0u);
  EXPECT_EQ(safety.peak_limited_ticks + safety.continuous_limited_ticks, 0u);
  EXPECT_EQ(safety.ticks, scheduler.trace().size());
  EXPECT_GT(safety.max_physical_force, 0.0);
}

TEST(SafetyWiringTest, ScalesAndSaturatesForADesktopDevice) {
  PressedRun run;
  testing::KinematicDevice device(-1e-3, 10e-3, {0.0, -(run.clearance() + 1e-6)});
  const DeviceSpec touch = LookupDeviceSpec("Touch");
  device.set_spec(touch);
  device.Start(1e-3);
  SchedulerSettings settings{1000.0, 0.3, ClockMode::kVirtual};
  settings.safety = RuntimeSafetySettings(Yaml("{coupling: direct, force_scale: 100}"), touch);
  Scheduler scheduler(device, run.positioning, run.constrained, settings);
  scheduler.Run();
  bool saturated = false;
  for (const TickRecord& r : scheduler.trace()) {
    ASSERT_LE(r.device_wrench.force.norm(), touch.max_force);
    ASSERT_TRUE(r.device_wrench.AllFinite());
    const Eigen::Vector3d scaled = 100.0 * r.wrench.force;
    if (scaled.norm() < 0.5 * touch.max_continuous_force) {
      ASSERT_NEAR((r.device_wrench.force - scaled).norm(), 0.0, 1e-12 * (1.0 + scaled.norm()));
    } else if (r.device_wrench.force.norm() < scaled.norm() * (1.0 - 1e-9)) {
      saturated = true;
      // Saturation keeps the direction.
      ASSERT_NEAR(r.device_wrench.force.normalized().dot(scaled.normalized()), 1.0, 1e-9);
    }
  }
  const SafetyReport& safety = scheduler.stats().safety;
  EXPECT_EQ(safety.force_scale, 100.0);
  // Scaled up, the fake press fit asks for more than the Touch's peak: the chain must have cut it.
  ASSERT_GT(100.0 * safety.max_physical_force, touch.max_force);
  EXPECT_TRUE(saturated);
  EXPECT_GT(safety.peak_limited_ticks + safety.continuous_limited_ticks, 0u);
  EXPECT_LE(safety.max_delivered_force, touch.max_force);
}

TEST(SafetyWiringTest, CoupledTheLawActsOnTheProxyAndTheHandFeelsTheSpring) {
  PressedRun run;
  // Pushing along the axis into a part whose fake law resists axially: the proxy lags the handle.
  testing::KinematicDevice device(-1e-3, 10e-3, {0.0, -(run.clearance() + 1e-6)});
  const DeviceSpec phantom = LookupDeviceSpec("PHANTOM Desktop");
  device.set_spec(phantom);
  device.Start(1e-3);
  SchedulerSettings settings{1000.0, 0.3, ClockMode::kVirtual};
  settings.safety = RuntimeSafetySettings(Yaml("{force_scale: 0.01}"), phantom);
  ASSERT_EQ(settings.safety.coupling, CouplingMode::kSpringDamper);
  Scheduler scheduler(device, run.positioning, run.constrained, settings);
  scheduler.Run();
  const SafetyReport& safety = scheduler.stats().safety;
  const CouplingGains gains = DefaultCouplingGains(phantom, 1e-3);
  EXPECT_EQ(safety.coupling_gains.stiffness, gains.stiffness);
  EXPECT_EQ(safety.coupling_gains.damping, gains.damping);
  bool lagged = false;
  for (const TickRecord& r : scheduler.trace()) {
    ASSERT_LE(r.device_wrench.force.norm(), phantom.max_force);
    const Eigen::Vector3d handle(0.0, -1e-3 + 10e-3 * r.time, -(run.clearance() + 1e-6));
    // The part (the proxy) never runs ahead of the handle pushing it.
    ASSERT_LE(r.position.y(), handle.y() + 1e-12);
    if (handle.y() - r.position.y() > 1e-7) lagged = true;
  }
  EXPECT_TRUE(lagged);
  // The handle meets the coupling spring in series with the scaled contact: softer than K_c.
  EXPECT_GT(device.stiffness(), 0.0);
  EXPECT_LT(device.stiffness(), gains.stiffness);
  EXPECT_EQ(safety.non_finite_faults, 0u);

  // A second run of the same scheduler starts the proxy afresh: identical trace.
  std::vector<std::string> first;
  for (auto r : scheduler.trace()) {
    r.compute_us = 0.0;
    first.push_back(TraceRow(r));
  }
  device.Start(1e-3);
  scheduler.Run();
  ASSERT_EQ(scheduler.trace().size(), first.size());
  for (std::size_t k = 0; k < first.size(); ++k) {
    auto r = scheduler.trace()[k];
    r.compute_us = 0.0;
    ASSERT_EQ(TraceRow(r), first[k]) << "tick " << k;
  }
}

TEST(SafetyWiringTest, CouplingADeviceWithoutDampingIsRefused) {
  PressedRun run;
  testing::KinematicDevice device(-1e-3, 10e-3);
  device.Start(1e-3);
  SchedulerSettings settings{1000.0, 0.1, ClockMode::kVirtual};
  settings.safety = RuntimeSafetySettings(Yaml("{coupling: spring_damper}"), device.spec());
  EXPECT_THROW(Scheduler(device, run.positioning, run.constrained, settings), UserError);
  settings.safety = RuntimeSafetySettings(Yaml("{physical_full_scale: 100 N}"), device.spec());
  EXPECT_THROW(Scheduler(device, run.positioning, run.constrained, settings), UserError);
}

TEST(SafetyWiringTest, RecordsTheDeviceStreamEveryTick) {
  PressedRun run;
  testing::KinematicDevice device(-1e-3, 10e-3, {0.0, -(run.clearance() + 1e-6)});
  device.Start(1e-3);
  SchedulerSettings settings{1000.0, 0.2, ClockMode::kVirtual};
  Scheduler plain(device, run.positioning, run.constrained, settings);
  plain.Run();
  EXPECT_TRUE(plain.recording().empty());

  settings.record = true;
  device.Start(1e-3);
  Scheduler scheduler(device, run.positioning, run.constrained, settings);
  scheduler.Run();
  const auto& trace = scheduler.trace();
  const auto& samples = scheduler.recording();
  ASSERT_EQ(samples.size(), trace.size());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    ASSERT_EQ(samples[k].time, trace[k].time);
    ASSERT_EQ(samples[k].position, trace[k].position);  // direct: the part is the handle
    ASSERT_EQ(samples[k].velocity.y(), 10e-3);
    ASSERT_TRUE(SameBits(samples[k].commanded, trace[k].device_wrench));
  }
}

}  // namespace
}  // namespace fitfeel
