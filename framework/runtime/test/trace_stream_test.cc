#include "framework/runtime/trace_stream.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "framework/core/error.h"
#include "framework/runtime/constrained_stage.h"
#include "framework/runtime/positioning_stage.h"
#include "framework/runtime/prepare.h"
#include "framework/runtime/run.h"
#include "framework/runtime/scheduler.h"
#include "framework/runtime/test/fake_scene.h"
#include "framework/runtime/test/output_files.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

fs::path StreamDir(const std::string& name) { return testing::FreshDir("stream", name); }
using testing::Lines;

std::size_t Entries(const fs::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++n;
  return n;
}

// The scene prepared once, with its two stages, for schedulers built by hand.
struct Stages {
  Scene scene = testing::MakeFakeScene(3, 0.5);
  PreparedScene prepared = Prepare(scene);
  PositioningStage positioning;
  ConstrainedStage constrained{*prepared.analyzer, *prepared.law};
};

// What the streamed outputs say is what the kept trace says: every row of a scheduler that keeps
// its trace, formatted after the run, equals the streamed trace.csv's row but for the measured
// tick time, and the summaries' statistics agree.
TEST(TraceStreamTest, StreamedTraceAndSummaryEqualTheKeptOnes) {
  Stages s;
  testing::KinematicDevice kept_device(-1e-3, 10e-3, {0.0, -20e-6});
  kept_device.Start(1e-3);
  Scheduler kept(kept_device, s.positioning, s.constrained, {1000.0, 0.5, ClockMode::kVirtual});
  kept.Run();

  const fs::path dir = StreamDir("equal");
  testing::KinematicDevice device(-1e-3, 10e-3, {0.0, -20e-6});
  device.Start(1e-3);
  // A ring of 8 rows: the virtual loop waits for the writer again and again, and loses nothing.
  TraceStream stream({dir, true, true, std::nullopt, {}}, nullptr, 8);
  SchedulerSettings settings{1000.0, 0.5, ClockMode::kVirtual};
  settings.stream = &stream.ring();
  Scheduler streamed(device, s.positioning, s.constrained, settings);
  streamed.Run();
  EXPECT_TRUE(streamed.trace().empty());  // nothing kept
  EXPECT_EQ(streamed.stats().dropped_rows, 0u);
  nlohmann::json summary;
  const OutputPaths paths = stream.Finish(RunInfo{}, streamed.stats(), &summary);
  EXPECT_EQ(paths.trace, dir / "trace.csv");
  EXPECT_EQ(Entries(dir), 2u);  // trace and summary, no temporaries

  const auto lines = Lines(dir / "trace.csv");
  ASSERT_EQ(lines.size(), kept.trace().size() + 1);
  EXPECT_EQ(lines[0], TraceHeader());
  for (std::size_t k = 0; k < kept.trace().size(); ++k) {
    TickRecord r = kept.trace()[k];
    // The tick time is measured: take the streamed one's.
    const std::string& line = lines[k + 1];
    std::size_t pos = 0;
    for (int i = 0; i < 6; ++i) pos = line.find(',', pos) + 1;
    r.compute_us = std::stod(line.substr(pos, line.find(',', pos) - pos));
    ASSERT_EQ(line, TraceRow(r)) << "tick " << k;
  }
  const nlohmann::json expected = MakeSummary(RunInfo{}, kept.trace(), kept.stats());
  for (const char* key : {"axial_resistance_N", "radial_resistance_N", "depth_mm",
                          "constrained_ticks", "interference_ticks", "elastic_limit"}) {
    EXPECT_EQ(summary[key], expected[key]) << key;
  }
  fs::remove_all(dir);
}

// A device that owns the clock (hardware) ticks in real time: when the writer falls behind (here
// it never drains: the ring has no consumer) the tick does not wait; the rows beyond the ring's
// room are dropped and counted.
class StreamServoDevice final : public Device {
 public:
  DeviceSpec DoSpec() const override { return testing::UnlimitedSpec(); }
  ClockOwner DoClockOwner() const override { return ClockOwner::kDevice; }
  void DoRunServoLoop(double duration, const std::function<bool(double)>& tick) override {
    for (int k = 0; k * 1e-3 < duration - 1e-9; ++k) {
      if (!tick(k * 1e-3)) break;
    }
  }

 protected:
  void DoConfigure(const ConfigNode&) override {}
  void DoStart(double) override {}
  void DoRead(double time, DeviceState* out) noexcept override {
    out->time = time;
    out->position = Eigen::Vector3d(0.0, -1e-3 + 1e-2 * time, 0.0);
  }
  void DoWrite(const Wrench&) noexcept override {}
};

TEST(TraceStreamTest, UnderARealTimeClockAFullRingDropsAndCountsRowsAndNeverWaits) {
  Stages s;
  StreamServoDevice device;
  device.Start(1e-3);
  SpscRing<StreamRow> ring(16);  // nobody pops
  SchedulerSettings settings{1000.0, 0.2, ClockMode::kRealTime};
  settings.stream = &ring;
  Scheduler scheduler(device, s.positioning, s.constrained, settings);
  scheduler.Run();
  EXPECT_EQ(scheduler.stats().ticks, 200u);
  EXPECT_EQ(scheduler.stats().dropped_rows, 200u - 16u);
  StreamRow row;
  for (std::uint64_t k = 0; k < 16; ++k) {
    ASSERT_TRUE(ring.TryPop(&row));
    EXPECT_EQ(row.index, k);  // the first rows kept, in order
  }
}

// A stream that never finishes (the run failed) leaves no file and removes the folder it made.
TEST(TraceStreamTest, AnUnfinishedStreamLeavesNothing) {
  const fs::path dir = StreamDir("unfinished");
  {
    TraceStream stream({dir, true, true, RecordingInfo{"x"}, {}});
    StreamRow row;
    row.has_sample = true;
    ASSERT_TRUE(stream.ring().TryPush(row));
    EXPECT_TRUE(fs::exists(dir));
  }
  EXPECT_FALSE(fs::exists(dir));
}

// A row the recording refuses (a non-finite sample) fails Finish with the reason; nothing stays.
TEST(TraceStreamTest, ARefusedRecordingSampleFailsTheRunAndLeavesNothing) {
  const fs::path dir = StreamDir("refused");
  fs::create_directories(dir);
  TraceStream stream({dir, true, true, RecordingInfo{"x"}, {}});
  StreamRow row;
  row.has_sample = true;
  row.sample.velocity.x() = std::numeric_limits<double>::quiet_NaN();
  ASSERT_TRUE(stream.ring().TryPush(row));
  try {
    stream.Finish(RunInfo{}, RunStats{}, nullptr);
    ADD_FAILURE() << "a non-finite sample was written";
  } catch (const UserError& e) {
    EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
  }
  EXPECT_EQ(Entries(dir), 0u);  // the folder was there before: kept, empty
  fs::remove_all(dir);
}

// A device whose state turns absurd on some ticks: not finite, or far beyond any workspace.
class GlitchingDevice final : public Device {
 public:
  DeviceSpec DoSpec() const override { return testing::UnlimitedSpec(); }
  std::vector<Wrench> written;

 protected:
  void DoConfigure(const ConfigNode&) override {}
  void DoStart(double) override {}
  void DoRead(double time, DeviceState* out) noexcept override {
    const int k = static_cast<int>(std::lround(time * 1000.0));
    out->time = time;
    out->position = Eigen::Vector3d(0.0, -1e-3 + 1e-2 * time, -20e-6);
    out->velocity = Eigen::Vector3d(0.0, 1e-2, 0.0);
    if (k % 50 == 10) out->position.y() = std::numeric_limits<double>::quiet_NaN();
    if (k % 50 == 20) out->position.x() = 1e9;  // a kilometre-scale encoder glitch
    if (k % 50 == 30) out->velocity.z() = std::numeric_limits<double>::infinity();
  }
  void DoWrite(const Wrench& w) noexcept override { written.push_back(w); }
};

TEST(TraceStreamTest, AbsurdDeviceStatesAreHeldZeroForcedFlaggedAndCounted) {
  auto device = std::make_shared<GlitchingDevice>();
  device->written.reserve(1000);
  const fs::path dir = StreamDir("glitch");
  RunOptions options;
  options.out_dir = dir;
  Scene scene = testing::MakeFakeScene(3, 0.5, device);
  scene.run.write_recording = true;
  const RunResult result = RunScene(std::move(scene), options);
  EXPECT_EQ(result.stats.device_faults, 30u);  // 3 of every 50 ticks over 500
  EXPECT_EQ(result.summary["device_faults"], 30);
  const auto lines = Lines(dir / "trace.csv");
  ASSERT_EQ(lines.size(), 501u);
  int flagged = 0;
  // The device_fault column's place: the header's commas before it.
  const std::string& header = lines[0];
  const auto column = std::count(header.begin(), header.begin() + header.find("device_fault"), ',');
  for (std::size_t k = 1; k < lines.size(); ++k) {
    EXPECT_EQ(lines[k].find("nan"), std::string::npos) << lines[k];
    EXPECT_EQ(lines[k].find("inf"), std::string::npos) << lines[k];
    std::size_t at = 0;
    for (auto c = column; c > 0; --c) at = lines[k].find(',', at) + 1;
    const bool fault = lines[k][at] == '1';
    const int tick = static_cast<int>(k) - 1;
    EXPECT_EQ(fault, tick % 50 == 10 || tick % 50 == 20 || tick % 50 == 30) << tick;
    if (fault) {
      ++flagged;
      EXPECT_TRUE(device->written[tick].force.isZero()) << tick;
    }
  }
  EXPECT_EQ(flagged, 30);
  // The recording holds the held (sane) states and reads back.
  EXPECT_EQ(ReadRecording(dir / "recording.csv").samples.size(), 500u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace fitfeel
