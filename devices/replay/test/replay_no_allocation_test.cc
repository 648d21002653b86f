// Read and Write run in the tick: they must not allocate.
#include "devices/replay/replay_device.h"

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>

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
  allocations = 0;
  counting = true;
  auto probe = std::make_unique<int>(1);  // the counter works
  const long baseline = allocations.load();
  for (int k = 0; k < 3000; ++k) {
    DeviceState state;
    device.Read(k * 1e-3, &state);
    Wrench w;
    w.force.y() = state.position.y();
    device.Write(w);
  }
  counting = false;
  EXPECT_EQ(baseline, 1);
  EXPECT_EQ(allocations.load(), baseline);
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace fitfeel
