// The per-tick path must not allocate: count every operator new while the chain ticks.
#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>

// Framework headers first: the skeleton's framework/core/quantity.h names a parameter si_value,
// which <signal.h> (pulled in by gtest) defines as a macro.
#include "framework/device/device_specs.h"
#include "framework/safety/safety_chain.h"

#include <gtest/gtest.h>

namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace fitfeel {
namespace {

TEST(SafetyChainTick, CounterSeesAllocations) {
  allocations = 0;
  counting = true;
  auto probe = std::make_unique<double>(1.0);
  counting = false;
  EXPECT_EQ(allocations.load(), 1);
}

TEST(SafetyChainTick, DoesNotAllocate) {
  for (CouplingMode mode : {CouplingMode::kDirect, CouplingMode::kSpringDamper}) {
    SafetySettings s;
    s.coupling = mode;
    s.force_scale = 0.01;
    s.passivity_controller = true;
    SafetyChain chain;
    chain.Configure(s, LookupDeviceSpec("PHANTOM Desktop"), 1e-3);
    DeviceState device;
    Wrench physical;
    allocations = 0;
    counting = true;
    for (int k = 0; k < 2000; ++k) {
      device.position.y() = 0.001 * std::sin(k * 0.01);
      device.velocity.y() = 0.01 * std::cos(k * 0.01);
      DeviceState law;
      chain.SimulatedState(device, &law);
      physical.force.y() = 2e6 * std::max(0.0, -law.position.y());
      if (k == 500) physical.force.x() = std::nan("");
      if (k == 501) physical.force.x() = 0.0;
      chain.SetEnvironmentStiffness(2e6);
      const Wrench out = chain.Apply(physical, device, 1e-3);
      ASSERT_TRUE(out.AllFinite());
    }
    counting = false;
    EXPECT_EQ(allocations.load(), 0) << "mode " << static_cast<int>(mode);
  }
}

}  // namespace
}  // namespace fitfeel
