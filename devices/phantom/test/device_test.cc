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
    for (const char* name : {"FAKEHD_INIT_FAIL", "FAKEHD_CALIBRATION", "FAKEHD_CALIBRATION_STYLES",
                             "FAKEHD_FORCE_ERROR_FRAME", "FAKEHD_MODEL", "FAKEHD_MAX_FORCE",
                             "FAKEHD_MAX_CONTINUOUS_FORCE"}) {
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

TEST_F(PhantomTest, CalibrationUpdateIsRunAutomatically) {
  setenv("FAKEHD_CALIBRATION", "update", 1);
  PhantomDevice device;
  EXPECT_EQ(StartError(device), "");
  EXPECT_EQ(Stats().calibration_updates, 1u);
  EXPECT_EQ(Stats().force_output_enabled, 1u);
  device.Stop();
  EXPECT_EQ(Stats().initialized, 0u);
}

TEST_F(PhantomTest, CalibrationThatNeedsTheUserIsRefused) {
  setenv("FAKEHD_CALIBRATION", "manual", 1);
  PhantomDevice device;
  std::string what = StartError(device);
  EXPECT_NE(what.find("inkwell"), std::string::npos) << what;
  EXPECT_EQ(Stats().initialized, 0u);  // the device was disabled again
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
  EXPECT_DOUBLE_EQ(spec.max_stiffness, 700.0);
  EXPECT_EQ(device.diagnostics().hd_model, "PHANTOM Omni");
  EXPECT_EQ(device.clock_owner(), ClockOwner::kDevice);

  setenv("FAKEHD_MODEL", "Prototype 9000", 1);  // unknown: the driver's nominal values
  PhantomDevice other;
  ASSERT_EQ(StartError(other), "");
  EXPECT_EQ(other.spec().model, "Prototype 9000");
  EXPECT_DOUBLE_EQ(other.spec().max_stiffness, 1000.0);  // 1 N/mm
  EXPECT_DOUBLE_EQ(other.spec().damping, 5.0);           // 0.005 N*s/mm
  EXPECT_NEAR(other.spec().workspace.x(), 0.160, 1e-12);
}

TEST_F(PhantomTest, ServoLoopRunsTenSecondsAtOneKilohertz) {
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
    // The fake's stylus: z fixed at 15 mm, x-y on a 20 mm circle.
    units_ok = units_ok && state.position.z() == 0.015 &&
               std::abs(state.position.head<2>().norm() - 0.020) < 1e-9;
    Wrench w;
    w.force = Eigen::Vector3d(0.0, -0.5, 0.0);
    device.Write(w);
    ++ticks;
    return true;
  };
  device.RunServoLoop(10.0, tick);
  const FakeHdStats stats = Stats();
  std::printf("servo run: %ld ticks in %.3f s of servo thread (%llu frames)\n", ticks,
              stats.servo_seconds, static_cast<unsigned long long>(stats.frames));
  // 10 s at 1 kHz; the fake skips ticks it wakes up too late for, and this machine is shared, so
  // the bound is loose below and tight above.
  EXPECT_GE(ticks, 7000);
  EXPECT_LE(ticks, 10002);
  EXPECT_EQ(static_cast<std::uint64_t>(ticks), stats.frames);
  EXPECT_EQ(stats.frame_errors, 0u);
  EXPECT_TRUE(monotonic);
  EXPECT_TRUE(units_ok);
  EXPECT_NEAR(stats.max_force, 0.5, 1e-12);
  EXPECT_EQ(stats.last_force[1], 0.0);  // the last frame leaves the device without force
  EXPECT_GE(last_time, 10.0 - 0.01);
  EXPECT_EQ(device.diagnostics().force_errors, 0u);
  device.Stop();
}

TEST_F(PhantomTest, ForceLimitErrorZeroesForceThenRecovers) {
  setenv("FAKEHD_FORCE_ERROR_FRAME", "200", 1);
  PhantomDevice device;
  ASSERT_EQ(StartError(device), "");
  long ticks = 0;
  const std::function<bool(double)> tick = [&](double time) {
    DeviceState state;
    device.Read(time, &state);
    Wrench w;
    w.force = Eigen::Vector3d(0.0, 1.0, 0.0);
    device.Write(w);
    return ++ticks < 600;
  };
  device.RunServoLoop(5.0, tick);
  const PhantomDiagnostics d = device.diagnostics();
  const FakeHdStats stats = Stats();
  EXPECT_EQ(stats.error_frame, 200u);
  EXPECT_EQ(d.force_errors, 1u);
  EXPECT_EQ(d.last_error, static_cast<std::uint32_t>(HD_EXCEEDED_MAX_FORCE));
  EXPECT_EQ(d.zeroed_ticks, 100u);
  EXPECT_EQ(stats.nonzero_after_error, 0u);  // zero force right after the error
  EXPECT_EQ(ticks, 600);                     // the run went on
  EXPECT_EQ(stats.frames, 600u);
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
