// The per-tick path must not allocate: count every operator new while the chain ticks.
#include <algorithm>
#include <cmath>
#include <memory>

// Framework headers first: the skeleton's framework/core/quantity.h names a parameter si_value,
// which <signal.h> (pulled in by gtest) defines as a macro.
#include "framework/device/device_specs.h"
#include "framework/safety/safety_chain.h"
#include "framework/testing/allocation_counter.h"

#include <gtest/gtest.h>

namespace fitfeel {
namespace {

TEST(SafetyChainTick, CounterSeesAllocations) {
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  test_support::ScopedAllocationCounter allocations;
  auto probe = std::make_unique<double>(1.0);
  allocations.Stop();
  EXPECT_EQ(allocations.count(), 1);
}

TEST(SafetyChainTick, DoesNotAllocate) {
  for (CouplingMode mode : {CouplingMode::kDirect, CouplingMode::kSpringDamper}) {
    SafetySettings s;
    s.coupling = mode;
    s.force_scale = 0.01;
    s.passivity_controller = true;
    SafetyChain chain;
    chain.Configure(s, LookupDeviceSpec("PHANTOM Desktop"), 1e-3);
    PartState device;
    Wrench physical;
    FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
    test_support::ScopedAllocationCounter allocations;
    for (int k = 0; k < 2000; ++k) {
      device.position.y() = 0.001 * std::sin(k * 0.01);
      device.velocity.y() = 0.01 * std::cos(k * 0.01);
      PartState law;
      chain.SimulatedState(device, &law);
      physical.force.y() = 2e6 * std::max(0.0, -law.position.y());
      if (k == 500) physical.force.x() = std::nan("");
      if (k == 501) physical.force.x() = 0.0;
      chain.SetEnvironmentStiffness(2e6);
      const Wrench out = chain.Apply(physical, device, 1e-3);
      ASSERT_TRUE(out.AllFinite());
    }
    allocations.Stop();
    EXPECT_EQ(allocations.count(), 0) << "mode " << static_cast<int>(mode);
  }
}

}  // namespace
}  // namespace fitfeel
