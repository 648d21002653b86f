#include "devices/phantom/phantom_device.h"

#include <dlfcn.h>

#include <cmath>
#include <cstdlib>
#include <memory>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/plugin/abi.h"
#include "tests/fakehd/fake_hd.h"

extern "C" const FitfeelPluginDescriptor* fitfeel_plugin_register();

namespace fitfeel::phantom {
namespace {

// Each test sets the fake's scenario through the environment, which the fake reads in
// hdInitDevice, and points the plugin at the fake library.
class PhantomTest : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* name :
         {"FAKEHD_INIT_FAIL", "FAKEHD_CALIBRATION", "FAKEHD_CALIBRATION_STYLES",
          "FAKEHD_MANUAL_SECONDS", "FAKEHD_FORCE_ERROR_FRAME", "FAKEHD_VELOCITY_ERROR_FRAME",
          "FAKEHD_WARM_FRAME", "FAKEHD_TEMPERATURE", "FAKEHD_COOL_SECONDS", "FAKEHD_WATCHDOG_MS", "FAKEHD_RATE",
          "FAKEHD_PATH", "FAKEHD_MODEL", "FAKEHD_MAX_FORCE", "FAKEHD_MAX_CONTINUOUS_FORCE",
          "FAKEHD_MAX_STIFFNESS"}) {
      unsetenv(name);
    }
    setenv("FITFEEL_HD_LIBRARY", FITFEEL_FAKE_HD_LIBRARY, 1);
  }
  void TearDown() override { unsetenv("FITFEEL_HD_LIBRARY"); }

  static FakeHdStats Stats() {
    void* handle = dlopen(FITFEEL_FAKE_HD_LIBRARY, RTLD_NOW | RTLD_NOLOAD);
    EXPECT_NE(handle, nullptr) << "the plugin did not load the fake library";
    FakeHdStats stats{};
    if (handle == nullptr) return stats;
    auto fn = reinterpret_cast<FakeHdStatsFn>(dlsym(handle, "fakehd_stats"));
    fn(&stats);
    dlclose(handle);
    return stats;
  }

  // Runs `ticks` servo ticks writing `force` (scene frame); `seen(k, state)` sees each tick's
  // state, whose `delivered` is what the device was sent in the previous tick.
  static long ConstantForce(PhantomDevice& device, const Eigen::Vector3d& force, long ticks,
                            const std::function<void(long, const DeviceState&)>& seen = {}) {
    long done = 0;
    const std::function<bool(double)> tick = [&](double time) {
      DeviceState state;
      device.Read(time, &state);
      if (seen) seen(done, state);
      Wrench w;
      w.force = force;
      device.Write(w);
      return ++done < ticks;
    };
    device.RunServoLoop(10.0, tick);
    return done;
  }

  static std::string StartError(PhantomDevice& device) {
    try {
      device.Start(1e-3);
    } catch (const UserError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(PhantomTest, RefusesWhenTheLibraryIsAbsentNamingWhatItTried) {
  setenv("FITFEEL_HD_LIBRARY", "/nonexistent/openhaptics/libHD.so", 1);
  PhantomDevice device;
  const std::string what = StartError(device);
  EXPECT_NE(what.find("OpenHaptics HD library (libHD.so)"), std::string::npos) << what;
  EXPECT_NE(what.find("/nonexistent/openhaptics/libHD.so"), std::string::npos) << what;
  EXPECT_NE(what.find("FITFEEL_HD_LIBRARY"), std::string::npos) << what;
}

TEST_F(PhantomTest, WithoutTheVariableSearchesTheUsualPlaces) {
  unsetenv("FITFEEL_HD_LIBRARY");
  if (void* real = dlopen("libHD.so", RTLD_NOW | RTLD_NOLOAD); real != nullptr) {
    dlclose(real);
    GTEST_SKIP() << "a libHD.so is loaded in this process";
  }
  if (void* real = dlopen("libHD.so", RTLD_LAZY); real != nullptr) {
    dlclose(real);
    GTEST_SKIP() << "this machine has an OpenHaptics library installed";
  }
  PhantomDevice device;
  const std::string what = StartError(device);
  EXPECT_NE(what.find("libHD.so:"), std::string::npos) << what;
  EXPECT_NE(what.find("/usr/lib/libHD.so"), std::string::npos) << what;
}

TEST_F(PhantomTest, InitFailureIsReportedFromTheErrorStack) {
  setenv("FAKEHD_INIT_FAIL", "1", 1);
  PhantomDevice device;
  const std::string what = StartError(device);
  EXPECT_NE(what.find("hdInitDevice"), std::string::npos) << what;
  EXPECT_NE(what.find("HD_COMM_ERROR (0x0302)"), std::string::npos) << what;
  EXPECT_NE(what.find("internal code 5"), std::string::npos) << what;
  EXPECT_NE(what.find("Communication error (fake)"), std::string::npos) << what;
}

TEST_F(PhantomTest, CalibrationUpdateIsRunAutomaticallyInsideTheScheduler) {
  setenv("FAKEHD_CALIBRATION", "update", 1);
  PhantomDevice device;
  EXPECT_EQ(StartError(device), "");
  EXPECT_EQ(Stats().calibration_updates, 1u);
  EXPECT_EQ(Stats().calibration_outside_scheduler, 0u);  // the fake refuses those
  EXPECT_EQ(Stats().force_output_enabled, 1u);
  EXPECT_EQ(device.diagnostics().calibration, "updated (auto)");
  device.Stop();
  EXPECT_EQ(Stats().initialized, 0u);
}

TEST_F(PhantomTest, ManualCalibrationWaitsForTheUserWithinTheTimeout) {
  setenv("FAKEHD_CALIBRATION", "manual", 1);
  setenv("FAKEHD_MANUAL_SECONDS", "0.3", 1);  // the "user" inkwells the stylus after 0.3 s
  PhantomSettings settings;
  settings.calibration_timeout = 5.0;
  PhantomDevice device;
  device.Configure(settings);
  EXPECT_EQ(StartError(device), "");
  EXPECT_EQ(device.diagnostics().calibration, "manual");
  EXPECT_GE(device.diagnostics().calibration_wait, 0.25);
  EXPECT_LT(device.diagnostics().calibration_wait, 5.0);
  device.Stop();

  settings.calibration_timeout = 0.2;  // the user is slower than the timeout
  setenv("FAKEHD_MANUAL_SECONDS", "10", 1);
  PhantomDevice late;
  late.Configure(settings);
  const std::string what = StartError(late);
  EXPECT_NE(what.find("calibration_timeout"), std::string::npos) << what;
  EXPECT_EQ(Stats().initialized, 0u);
}

TEST_F(PhantomTest, ServoRateMustMatchTheRunRate) {
  setenv("FAKEHD_RATE", "500", 1);
  PhantomDevice device;
  const std::string what = StartError(device);  // Start(1e-3): a 1 kHz run
  EXPECT_NE(what.find("500 Hz (HD_UPDATE_RATE)"), std::string::npos) << what;
  EXPECT_NE(what.find("run.rate is 1000 Hz"), std::string::npos) << what;
  EXPECT_EQ(Stats().initialized, 0u);
  PhantomDevice slow;
  EXPECT_NO_THROW(slow.Start(2e-3));
  EXPECT_DOUBLE_EQ(slow.spec().native_rate, 500.0);
  slow.Stop();
}

TEST_F(PhantomTest, CalibrationThatNeedsTheUserIsRefused) {
  setenv("FAKEHD_CALIBRATION", "manual", 1);
  PhantomSettings no_wait;
  no_wait.calibration_timeout = 0.0;
  PhantomDevice device;
  device.Configure(no_wait);
  std::string what = StartError(device);
  EXPECT_NE(what.find("inkwell"), std::string::npos) << what;
  EXPECT_EQ(Stats().initialized, 0u);  // the device was disabled again
  EXPECT_EQ(what.find("waiting"), std::string::npos);
  setenv("FAKEHD_CALIBRATION", "update", 1);
  setenv("FAKEHD_CALIBRATION_STYLES", "1", 1);  // encoder reset only
  what = StartError(device);
  EXPECT_NE(what.find("encoder-reset"), std::string::npos) << what;
  PhantomSettings no_auto;
  no_auto.auto_calibrate = false;
  unsetenv("FAKEHD_CALIBRATION_STYLES");
  PhantomDevice manual;
  manual.Configure(no_auto);
  what = StartError(manual);
  EXPECT_NE(what.find("auto_calibrate is off"), std::string::npos) << what;
}

TEST_F(PhantomTest, SpecComesFromTheDriverModelAndItsNominalLimits) {
  setenv("FAKEHD_MODEL", "PHANTOM Omni", 1);
  setenv("FAKEHD_MAX_FORCE", "3.0", 1);
  setenv("FAKEHD_MAX_CONTINUOUS_FORCE", "0.9", 1);
  PhantomDevice device;
  ASSERT_EQ(StartError(device), "");
  const DeviceSpec spec = device.spec();
  EXPECT_EQ(spec.model, "PHANTOM Omni");
  EXPECT_DOUBLE_EQ(spec.max_force, 3.0);              // driver's 3.0 < table's 3.3
  EXPECT_DOUBLE_EQ(spec.max_continuous_force, 0.88);  // table's 0.88 < driver's 0.9
  EXPECT_DOUBLE_EQ(spec.max_stiffness, 700.0);  // table's 700 < driver's 1000
  // No measured damping: the least that holds K_max stably at 1 kHz, K T / 2, never credited.
  EXPECT_DOUBLE_EQ(spec.damping, 700.0 * 1e-3 / 2.0);
  EXPECT_FALSE(spec.credit_damping);
  EXPECT_EQ(device.diagnostics().hd_model, "PHANTOM Omni");
  EXPECT_EQ(device.clock_owner(), ClockOwner::kDevice);

  device.Stop();  // one scheduler per process, as in the SDK
  setenv("FAKEHD_MODEL", "Prototype 9000", 1);  // unknown: the driver's nominal values
  PhantomDevice other;
  ASSERT_EQ(StartError(other), "");
  EXPECT_EQ(other.spec().model, "Prototype 9000");
  EXPECT_DOUBLE_EQ(other.spec().max_stiffness, 1000.0);  // 1 N/mm
  // HD_NOMINAL_MAX_DAMPING is what the device can render, not what it has: not used.
  EXPECT_DOUBLE_EQ(other.spec().damping, 0.5);
  EXPECT_NEAR(other.spec().workspace.x(), 0.160, 1e-12);
  other.Stop();

  setenv("FAKEHD_MODEL", "Touch", 1);
  setenv("FAKEHD_MAX_STIFFNESS", "0.3", 1);  // a driver stiffer-limited than the table
  PhantomDevice touch;
  ASSERT_EQ(StartError(touch), "");
  EXPECT_DOUBLE_EQ(touch.spec().max_stiffness, 300.0);
  EXPECT_DOUBLE_EQ(touch.spec().damping, 0.15);
}

TEST_F(PhantomTest, AMeasuredDampingIsKept) {
  PhantomDevice device;
  device.Configure(ConfigNode::Parse("{model: Touch, spec: {damping: 0.6 N*s/m}}",
                              "scene.yaml", "device"));
  ASSERT_EQ(StartError(device), "");
  EXPECT_DOUBLE_EQ(device.spec().damping, 0.6);
  EXPECT_FALSE(device.spec().credit_damping);
}

TEST_F(PhantomTest, ServoLoopRunsThreeSecondsAtOneKilohertzInTheSceneFrame) {
  PhantomDevice device;
  ASSERT_EQ(StartError(device), "");
  long ticks = 0;
  double last_time = -1.0;
  bool monotonic = true;
  bool units_ok = true;
  const std::function<bool(double)> tick = [&](double time) {
    DeviceState state;
    device.Read(time, &state);
    monotonic = monotonic && state.time > last_time;
    last_time = state.time;
    // The fake's stylus: device z fixed at 15 mm, x-y on a 20 mm circle. The default frame
    // (scene x, y, z = device x, -z, y; origin at device z = -20 mm) puts it 35 mm before the
    // entrance, circling in the scene's x-z plane.
    units_ok = units_ok && std::abs(state.position.y() + 0.035) < 1e-12 &&
               std::abs(std::hypot(state.position.x(), state.position.z()) - 0.020) < 1e-9;
    Wrench w;
    w.force = Eigen::Vector3d(0.0, -0.5, 0.0);
    device.Write(w);
    ++ticks;
    return true;
  };
  device.RunServoLoop(3.0, tick);
  const FakeHdStats stats = Stats();
  std::printf("servo run: %ld ticks in %.3f s of servo thread (%llu frames)\n", ticks,
              stats.servo_seconds, static_cast<unsigned long long>(stats.frames));
  // 3 s at 1 kHz on the fake's clock, which counts servo periods: ticks at 0, 1, ..., 3000 ms
  // (the one at 3 s sends the closing zero), however loaded the machine.
  EXPECT_EQ(ticks, 3001);
  EXPECT_EQ(static_cast<std::uint64_t>(ticks) + 1, stats.frames);  // + the calibration frame
  EXPECT_EQ(stats.frame_errors, 0u);
  EXPECT_TRUE(monotonic);
  EXPECT_TRUE(units_ok);
  EXPECT_NEAR(stats.max_force, 0.5, 1e-12);
  // Scene -y is device +z; the motors hold the last force set, which is zero.
  EXPECT_EQ(stats.last_force[0], 0.0);
  EXPECT_EQ(stats.last_force[1], 0.0);
  EXPECT_EQ(stats.last_force[2], 0.0);
  EXPECT_GE(last_time, 3.0 - 0.01);
  EXPECT_GT(device.diagnostics().mean_period, 0.9e-3);
  EXPECT_EQ(device.diagnostics().update_rate, 1000.0);
  EXPECT_EQ(device.diagnostics().force_errors, 0u);
  device.Stop();
}

TEST_F(PhantomTest, ForceLimitErrorZeroesForceThenRampsBack) {
  setenv("FAKEHD_FORCE_ERROR_FRAME", "200", 1);
  PhantomDevice device;
  ASSERT_EQ(StartError(device), "");
  const long ticks = ConstantForce(device, Eigen::Vector3d(0.0, 1.0, 0.0), 600);
  const PhantomDiagnostics d = device.diagnostics();
  const FakeHdStats stats = Stats();
  EXPECT_EQ(stats.error_frame, 200u);
  EXPECT_EQ(d.force_errors, 1u);
  EXPECT_EQ(d.last_error, static_cast<std::uint32_t>(HD_EXCEEDED_MAX_FORCE));
  // Back from zero over ramp_time: 0.25 s of 1 ms periods on the fake's clock.
  EXPECT_GE(d.ramped_ticks, 249u);
  EXPECT_LE(d.ramped_ticks, 251u);
  EXPECT_EQ(ticks, 600);  // the run went on
  EXPECT_EQ(stats.frames, 601u);
  EXPECT_FALSE(d.stopped_on_faults);
}

TEST_F(PhantomTest, VelocityErrorRampsTheForceBack) {
  setenv("FAKEHD_VELOCITY_ERROR_FRAME", "100", 1);
  PhantomDevice device;
  ASSERT_EQ(StartError(device), "");
  double first_after = -1.0, later = -1.0;
  ConstantForce(device, Eigen::Vector3d(0.0, 2.0, 0.0), 600, [&](long k, const DeviceState& s) {
    if (k == 102) first_after = s.delivered.force.norm();
    if (k == 500) later = s.delivered.force.norm();
  });
  const PhantomDiagnostics d = device.diagnostics();
  EXPECT_EQ(d.velocity_errors, 1u);
  EXPECT_LT(first_after, 0.1);  // a small fraction right after the error
  EXPECT_NEAR(later, 2.0, 1e-9);
  const DeviceReport report = device.report();
  ASSERT_NE(report.Find("velocity_errors"), nullptr);
  EXPECT_EQ(std::get<std::uint64_t>(*report.Find("velocity_errors")), 1u);
}

TEST_F(PhantomTest, WarmMotorsHoldTheForceOffUntilCoolThenDerate) {
  setenv("FAKEHD_WARM_FRAME", "100", 1);
  setenv("FAKEHD_COOL_SECONDS", "0.1", 1);
  PhantomDevice device;
  ASSERT_EQ(StartError(device), "");
  ConstantForce(device, Eigen::Vector3d(0.0, 1.0, 0.0), 1000);
  const PhantomDiagnostics d = device.diagnostics();
  const FakeHdStats stats = Stats();
  // One HD_WARM_MOTORS: the plugin stops commanding force until the motors are below the derating
  // threshold, so the persistent fake raises no second one.
  EXPECT_EQ(d.warm_motor_errors, 1u);
  EXPECT_EQ(stats.warm_errors, 1u);
  // Cooling from 1 to 0.8 with a 0.1 s constant towards 0.2: 0.1 ln(0.8 / 0.6) = 29 ms.
  EXPECT_GE(d.zeroed_ticks, 25u);
  EXPECT_LE(d.zeroed_ticks, 35u);
  EXPECT_GT(d.ramped_ticks, 0u);
  EXPECT_NEAR(d.max_motor_temperature, 1.0, 1e-12);
  EXPECT_NEAR(stats.last_force[0] + stats.last_force[1] + stats.last_force[2], 0.0, 0.0);
  EXPECT_FALSE(d.stopped_on_faults);
}

TEST_F(PhantomTest, WarmMotorsDerateTheForce) {
  setenv("FAKEHD_TEMPERATURE", "0.85", 1);  // a quarter of the way from 0.8 to the cut-off
  PhantomDevice device;
  ASSERT_EQ(StartError(device), "");
  double delivered = 0.0;
  ConstantForce(device, Eigen::Vector3d(0.0, 2.0, 0.0), 50,
                [&](long, const DeviceState& s) { delivered = s.delivered.force.norm(); });
  EXPECT_NEAR(delivered, 2.0 * 0.75, 1e-9);
  EXPECT_EQ(device.diagnostics().derated_ticks, 50u);
}

TEST_F(PhantomTest, RepeatedFaultsStopTheRunCleanly) {
  // The watchdog faults every frame when frames come later than it allows.
  setenv("FAKEHD_WATCHDOG_MS", "0.001", 1);
  PhantomDevice device;
  ASSERT_EQ(StartError(device), "");
  // Returns: a stop on faults is not an error of the loop.
  const long ticks = ConstantForce(device, Eigen::Vector3d(0.0, 1.0, 0.0), 3000);
  const PhantomDiagnostics d = device.diagnostics();
  EXPECT_TRUE(d.stopped_on_faults);
  EXPECT_EQ(d.force_errors, 5u);
  EXPECT_LT(ticks, 3000);
  const FakeHdStats stats = Stats();
  EXPECT_EQ(stats.last_force[0], 0.0);
  EXPECT_EQ(stats.last_force[1], 0.0);
  EXPECT_EQ(stats.last_force[2], 0.0);
}

TEST_F(PhantomTest, FrameMapsAxesAndTheZeroButtonSetsTheOrigin) {
  // The circle path presses button 1 during odd seconds.
  PhantomSettings settings;
  settings.frame.zero_button = 1;
  settings.frame.home = Eigen::Vector3d(0.0, -0.010, 0.0);
  PhantomDevice device;
  device.Configure(settings);
  ASSERT_EQ(StartError(device), "");
  DeviceState before, at_press;
  long ticks = 0;
  bool was_pressed = false;
  const std::function<bool(double)> tick = [&](double time) {
    DeviceState state;
    device.Read(time, &state);
    if (ticks == 10) before = state;
    if (state.buttons != 0 && !was_pressed) at_press = state;
    was_pressed = state.buttons != 0;
    ++ticks;
    return state.buttons == 0 || ticks < 1100;
  };
  device.RunServoLoop(3.0, tick);
  EXPECT_NEAR(before.position.y(), -0.035, 1e-12);  // default origin: device z = -20 mm
  EXPECT_EQ(device.diagnostics().zeroings, 1u);
  EXPECT_NEAR((at_press.position - Eigen::Vector3d(0.0, -0.010, 0.0)).norm(), 0.0, 1e-12);
  // The stylus's axis (its -z column) is the part's y axis: near the scene's y on this path,
  // tilted by the stylus's turns about every axis (up to 0.2 rad each).
  const Eigen::Matrix3d r = before.orientation.toRotationMatrix();
  EXPECT_GT(r(1, 1), std::cos(0.4));
}

TEST_F(PhantomTest, ForcesAboveTheDriverLimitAreClamped) {
  PhantomDevice device;
  ASSERT_EQ(StartError(device), "");
  long ticks = 0;
  const std::function<bool(double)> tick = [&](double) {
    Wrench w;
    w.force = Eigen::Vector3d(30.0, -40.0, 0.0);  // 50 N
    if (ticks == 10) w.force.x() = std::nan("");
    device.Write(w);
    return ++ticks < 100;
  };
  device.RunServoLoop(5.0, tick);
  const FakeHdStats stats = Stats();
  EXPECT_LE(stats.max_force, 7.9);
  EXPECT_GT(stats.max_force, 7.8);
  EXPECT_EQ(device.diagnostics().force_errors, 0u);  // never above the driver's limit
  EXPECT_GE(device.diagnostics().clamped_writes, 98u);
}

TEST_F(PhantomTest, RunServoLoopBeforeStartIsRefused) {
  PhantomDevice device;
  EXPECT_THROW(device.RunServoLoop(1.0, [](double) { return true; }), UserError);
}

TEST(PhantomPlugin, DescriptorAndFactory) {
  const FitfeelPluginDescriptor* d = fitfeel_plugin_register();
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->abi_version, FITFEEL_PLUGIN_ABI_VERSION);
  ASSERT_EQ(d->entry_count, 1u);
  EXPECT_STREQ(d->entries[0].id, "fitfeel.device.phantom");
  EXPECT_EQ(d->entries[0].kind, kFitfeelDevicePlugin);
  std::unique_ptr<Device> device(static_cast<Device*>(d->entries[0].factory()));
  EXPECT_EQ(device->clock_owner(), ClockOwner::kDevice);
}

}  // namespace
}  // namespace fitfeel::phantom
