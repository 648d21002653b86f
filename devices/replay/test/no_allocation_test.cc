// Read and Write run in the tick: they must not allocate.
#include "devices/replay/replay_device.h"

#include <filesystem>
#include <memory>
#include <vector>

#include "framework/testing/allocation_counter.h"

#include <gtest/gtest.h>

namespace fitfeel::replay {
namespace {

TEST(ReplayTick, ReadAndWriteDoNotAllocate) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "fitfeel_replay_no_allocation.rec";
  std::vector<RecordedSample> samples(1000);
  for (int i = 0; i < 1000; ++i) {
    samples[i].time = i * 1e-3;
    samples[i].position.y() = -1e-5 * i;
  }
  WriteRecording(file, {"Touch"}, samples);
  ReplaySettings settings;
  settings.file = file;
  settings.loop = true;
  settings.speed = 0.7;
  ReplayDevice device;
  device.Configure(settings);
  device.Start(1e-3);
  FITFEEL_SKIP_UNLESS_COUNTING_ALLOCATIONS();
  test_support::ScopedAllocationCounter allocations;
  auto probe = std::make_unique<int>(1);  // the counter works
  const long baseline = allocations.count();
  for (int k = 0; k < 3000; ++k) {
    DeviceState state;
    device.Read(k * 1e-3, &state);
    Wrench w;
    w.force.y() = state.position.y();
    device.Write(w);
  }
  allocations.Stop();
  EXPECT_EQ(baseline, 1);
  EXPECT_EQ(allocations.count(), baseline);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace fitfeel::replay
