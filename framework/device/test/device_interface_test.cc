#include "framework/device/device.h"

#include <functional>
#include <limits>

#include <gtest/gtest.h>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

// A device that counts what reaches its Do... methods.
class CountingDevice final : public Device {
 public:
  int servo_loops = 0;
  int writes = 0;
  Wrench last;

 protected:
  DeviceSpec DoSpec() const override { return DeviceSpec{}; }
  void DoConfigure(const ConfigNode&) override {}
  void DoStart(double) override {}
  void DoRead(double time, DeviceState* out) noexcept override { out->time = time; }
  void DoWrite(const Wrench& wrench) noexcept override {
    ++writes;
    last = wrench;
  }
  void DoRunServoLoop(double, const std::function<bool(double)>&) override { ++servo_loops; }
};

// A device that owns no clock: the base's servo loop.
class PlainDevice final : public Device {
 protected:
  DeviceSpec DoSpec() const override { return DeviceSpec{}; }
  void DoConfigure(const ConfigNode&) override {}
  void DoStart(double) override {}
  void DoRead(double, DeviceState*) noexcept override {}
  void DoWrite(const Wrench&) noexcept override {}
};

// The public methods check their arguments once, for every plugin: what a plugin's Do... sees is
// always valid.
TEST(DeviceInterface, ThePublicMethodsCheckBeforeThePluginSeesAnything) {
  CountingDevice device;
  const std::function<bool(double)> tick = [](double) { return false; };
  EXPECT_THROW(device.RunServoLoop(0.0, tick), UserError);
  EXPECT_THROW(device.RunServoLoop(-1.0, tick), UserError);
  EXPECT_THROW(device.RunServoLoop(std::numeric_limits<double>::infinity(), tick), UserError);
  EXPECT_THROW(device.RunServoLoop(1.0, std::function<bool(double)>{}), UserError);
  EXPECT_EQ(device.servo_loops, 0);
  device.RunServoLoop(2.0, tick);
  EXPECT_EQ(device.servo_loops, 1);

  EXPECT_THROW(device.Start(0.0), UserError);
  Wrench bad;
  bad.force.x() = std::numeric_limits<double>::quiet_NaN();
  device.Write(bad);
  EXPECT_EQ(device.writes, 1);
  EXPECT_TRUE(device.last.AllFinite());  // a non-finite wrench reaches the device as zero
  EXPECT_EQ(device.last.force.norm(), 0.0);

  PlainDevice plain;
  EXPECT_THROW(plain.RunServoLoop(1.0, tick), UnsupportedError);
  EXPECT_EQ(plain.clock_owner(), ClockOwner::kFramework);
  EXPECT_TRUE(plain.active());
  EXPECT_TRUE(plain.report().empty());
}

}  // namespace
}  // namespace fitfeel
