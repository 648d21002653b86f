#include "devices/replay/replay_device.h"

#include <cmath>
#include <cstring>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/plugin/abi.h"
#include "framework/plugin/fingerprint.h"

extern "C" const FitfeelPluginDescriptor* fitfeel_plugin_register();

namespace fitfeel::replay {
namespace {

namespace fs = std::filesystem;

class ReplayTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           (std::string("fitfeel_replay_test_") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    // A hand pressing down along -y at 10 mm/s with a wobble, 1 kHz, 2 s.
    std::mt19937_64 rng(7);
    std::normal_distribution<double> noise(0.0, 1e-5);
    for (int i = 0; i <= 2000; ++i) {
      RecordedSample s;
      s.time = i * 1e-3;
      s.position = Eigen::Vector3d(noise(rng), 0.02 - 0.01 * s.time, noise(rng));
      s.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * s.time, Eigen::Vector3d::UnitY()));
      s.velocity = Eigen::Vector3d(0.0, -0.01, 0.0);
      s.angular_velocity = Eigen::Vector3d(0.0, 0.1, 0.0);
      s.buttons = (i >= 1000) ? 1u : 0u;
      s.commanded.force = Eigen::Vector3d(0.0, 0.5 * s.time, 0.0);
      s.delivered.force = s.commanded.force;
      samples_.push_back(s);
    }
    file_ = dir_ / "hand.rec";
    WriteRecording(file_, {"PHANTOM Desktop"}, samples_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  ReplaySettings Settings() const {
    ReplaySettings s;
    s.file = file_;
    return s;
  }

  fs::path dir_;
  fs::path file_;
  std::vector<RecordedSample> samples_;
};

bool BitEqual(const DeviceState& a, const DeviceState& b) {
  auto same = [](const double* x, const double* y, int n) {
    return std::memcmp(x, y, sizeof(double) * n) == 0;
  };
  return same(&a.time, &b.time, 1) && same(a.position.data(), b.position.data(), 3) &&
         same(a.orientation.coeffs().data(), b.orientation.coeffs().data(), 4) &&
         same(a.velocity.data(), b.velocity.data(), 3) &&
         same(a.angular_velocity.data(), b.angular_velocity.data(), 3) && a.buttons == b.buttons &&
         same(a.delivered.force.data(), b.delivered.force.data(), 3) &&
         same(a.delivered.torque.data(), b.delivered.torque.data(), 3);
}

TEST_F(ReplayTest, ReadsAtRecordedTimesReturnTheRecordedSamplesExactly) {
  ReplayDevice device;
  device.Configure(Settings());
  device.Start(1e-3);
  EXPECT_EQ(device.spec().model, "PHANTOM Desktop");
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    DeviceState state;
    device.Read(samples_[i].time, &state);
    ASSERT_EQ(std::memcmp(state.position.data(), samples_[i].position.data(), 24), 0) << i;
    ASSERT_EQ(
        std::memcmp(state.orientation.coeffs().data(), samples_[i].orientation.coeffs().data(), 32),
        0)
        << i;
    ASSERT_EQ(state.buttons, samples_[i].buttons);
    if (i + 1 < samples_.size()) {
      ASSERT_TRUE(device.active()) << i;
    }
  }
  EXPECT_FALSE(device.active());  // the last sample was read: the recording has ended
}

TEST_F(ReplayTest, RecordReplayRecordReproducesTheRunBitForBit) {
  // Replay the recording at the recorded tick times, record what the device reports, write and
  // read it back: the hand's stream is identical to the original.
  ReplayDevice device;
  device.Configure(Settings());
  device.Start(1e-3);
  std::vector<RecordedSample> again;
  for (std::size_t k = 0; device.active(); ++k) {
    DeviceState state;
    device.Read(static_cast<double>(k) * 1e-3, &state);
    RecordedSample s;
    s.time = state.time;
    s.position = state.position;
    s.orientation = state.orientation;
    s.velocity = state.velocity;
    s.angular_velocity = state.angular_velocity;
    s.buttons = state.buttons;
    again.push_back(s);
  }
  const fs::path copy = dir_ / "again.rec";
  WriteRecording(copy, {"PHANTOM Desktop"}, again);
  const Recording back = ReadRecording(copy);
  ASSERT_EQ(back.samples.size(), samples_.size());
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    const RecordedSample& a = samples_[i];
    const RecordedSample& b = back.samples[i];
    ASSERT_EQ(std::memcmp(&a.time, &b.time, 8), 0) << i;
    ASSERT_EQ(std::memcmp(a.position.data(), b.position.data(), 24), 0) << i;
    ASSERT_EQ(std::memcmp(a.velocity.data(), b.velocity.data(), 24), 0) << i;
    ASSERT_EQ(std::memcmp(a.orientation.coeffs().data(), b.orientation.coeffs().data(), 32), 0);
    ASSERT_EQ(a.buttons, b.buttons);
  }
}

TEST_F(ReplayTest, IdenticalInputsGiveIdenticalReads) {
  // Two devices, same file, same (irregular) read times and writes: identical states bit for bit.
  ReplaySettings settings = Settings();
  settings.speed = 1.37;
  settings.start = 0.123;
  settings.loop = true;
  ReplayDevice a, b;
  a.Configure(settings);
  b.Configure(settings);
  a.Start(1e-3);
  b.Start(1e-3);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> jitter(0.0, 2e-3);
  double t = 0.0;
  for (int k = 0; k < 5000; ++k) {
    t += jitter(rng);
    DeviceState sa, sb;
    a.Read(t, &sa);
    b.Read(t, &sb);
    ASSERT_TRUE(BitEqual(sa, sb)) << "read " << k;
    Wrench w;
    w.force = Eigen::Vector3d(std::sin(t), std::cos(t), t);
    a.Write(w);
    b.Write(w);
  }
}

TEST_F(ReplayTest, InterpolatesBetweenSamplesAndHonoursSpeedAndSeek) {
  ReplaySettings settings = Settings();
  settings.speed = 2.0;
  settings.start = 0.25;
  ReplayDevice device;
  device.Configure(settings);
  device.Start(1e-3);
  DeviceState state;
  // Run time 0.1 s -> recording time 0.25 + 0.2 = 0.45 s.
  device.Read(0.1, &state);
  EXPECT_NEAR(state.position.y(), 0.02 - 0.01 * 0.45, 1e-12);
  // Run time 0.10025 s -> 0.4505 s: halfway between two samples.
  device.Read(0.10025, &state);
  const double mid = 0.5 * (samples_[450].position.x() + samples_[451].position.x());
  EXPECT_NEAR(state.position.x(), mid, 1e-15);
  EXPECT_NEAR(state.position.y(), 0.02 - 0.01 * 0.4505, 1e-12);
  EXPECT_NEAR(Eigen::AngleAxisd(state.orientation).angle(), 0.1 * 0.4505, 1e-9);
  EXPECT_EQ(state.buttons, 0u);
  device.Read(0.5, &state);  // 1.25 s: button pressed since 1 s
  EXPECT_EQ(state.buttons, 1u);
  EXPECT_TRUE(device.active());
  device.Read(0.875, &state);  // 2.0 s: the end
  EXPECT_FALSE(device.active());
  device.Read(5.0, &state);  // held at the last sample
  EXPECT_EQ(state.position, samples_.back().position);
}

TEST_F(ReplayTest, LoopWrapsAround) {
  ReplaySettings settings = Settings();
  settings.loop = true;
  ReplayDevice device;
  device.Configure(settings);
  device.Start(1e-3);
  DeviceState first, wrapped;
  device.Read(0.3, &first);
  device.Read(2.3, &wrapped);  // one 2 s period later
  EXPECT_NEAR((first.position - wrapped.position).norm(), 0.0, 1e-12);
  device.Read(100.0, &wrapped);
  EXPECT_TRUE(device.active());
}

TEST_F(ReplayTest, DeliveredIsWhatWasWritten) {
  ReplayDevice device;
  device.Configure(Settings());
  device.Start(1e-3);
  Wrench w;
  w.force = Eigen::Vector3d(0.0, 1.5, 0.0);
  device.Write(w);
  DeviceState state;
  device.Read(0.0, &state);
  EXPECT_EQ(state.delivered.force, w.force);
}

TEST_F(ReplayTest, RefusesBadSettings) {
  ReplaySettings s = Settings();
  s.speed = 0.0;
  EXPECT_THROW(ReplayDevice().Configure(s), UserError);
  s = Settings();
  s.start = 3.0;  // past the 2 s recording
  EXPECT_THROW(ReplayDevice().Configure(s), UserError);
  s = Settings();
  s.file = dir_ / "missing.rec";
  EXPECT_THROW(ReplayDevice().Configure(s), RecordingError);
  WriteRecording(dir_ / "anonymous.rec", {}, samples_);
  s.file = dir_ / "anonymous.rec";
  EXPECT_THROW(ReplayDevice().Configure(s), UserError);  // no model anywhere
  s.model = "Touch";
  ReplayDevice touch;
  touch.Configure(s);
  EXPECT_EQ(touch.spec().model, "Touch");
  EXPECT_THROW(ReplayDevice().Start(1e-3), UserError);  // never configured
}

TEST(ReplayPlugin, DescriptorAndFactory) {
  const FitfeelPluginDescriptor* d = fitfeel_plugin_register();
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->abi_version, FITFEEL_PLUGIN_ABI_VERSION);
  EXPECT_EQ(d->descriptor_size, sizeof(FitfeelPluginDescriptor));
  EXPECT_STREQ(d->build_fingerprint, FITFEEL_BUILD_FINGERPRINT);
  ASSERT_EQ(d->entry_count, 1u);
  EXPECT_STREQ(d->entries[0].id, "fitfeel.device.replay");
  EXPECT_EQ(d->entries[0].kind, kFitfeelDevicePlugin);
  std::unique_ptr<Device> device(static_cast<Device*>(d->entries[0].factory()));
  EXPECT_NE(dynamic_cast<ReplayDevice*>(device.get()), nullptr);
}

}  // namespace
}  // namespace fitfeel::replay
