// One fixture, every device: the paper's case 1 scene runs through the real runtime (RunScene)
// with each device plugin in turn: the simulated robot, a replay of a recording made from the
// simulated run, and a Phantom driven through the fake HD library (tests/fakehd). The same
// invariants hold whatever the device:
//   - every wrench that reaches Device::Write is finite and within the device's peak force;
//   - the run has the planned number of ticks, one Read and one Write each;
//   - every recorded tick is finite.
// And for the replay: the run reproduces the recorded (simulated) run bit for bit.
//
// The device the scene configured is wrapped in a probe that forwards every call and keeps what
// crossed the device boundary, so the assertions see exactly what the device saw.
#include <dlfcn.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include "framework/core/error.h"
#include "framework/device/device.h"
#include "framework/device/recording.h"
#include "framework/plugin/registry.h"
#include "framework/runtime/run.h"
#include "framework/scenario/scene.h"
#include "framework/testing/source_tree.h"
#include "tests/fakehd/fake_hd.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

using ::fitfeel::test_support::kBuildTree;
using ::fitfeel::test_support::kSourceTree;
const fs::path kPaperScene = kSourceTree / "scenarios/paper-case1-h7js6.yaml";

// Forwards every call to the scene's device and keeps what crossed the boundary. Buffers are
// reserved in DoStart (before the loop), so the tick allocates nothing here either.
class ProbeDevice final : public Device {
 public:
  ProbeDevice(std::shared_ptr<Device> inner, std::size_t capacity)
      : inner_(std::move(inner)), capacity_(capacity) {}

  DeviceSpec DoSpec() const override { return inner_->spec(); }
  ClockOwner DoClockOwner() const override { return inner_->clock_owner(); }
  void DoRunServoLoop(double duration, const std::function<bool(double)>& tick) override {
    inner_->RunServoLoop(duration, tick);
  }
  bool DoActive() const override { return inner_->active(); }
  DeviceReport DoReport() const override { return inner_->report(); }

  const std::vector<RecordedSample>& samples() const { return samples_; }
  std::size_t reads() const { return reads_; }
  std::size_t writes() const { return writes_; }
  std::size_t overflow() const { return overflow_; }

 protected:
  void DoConfigure(const ConfigNode& node) override { inner_->Configure(node); }
  void DoStart(double period) override {
    samples_.clear();
    samples_.reserve(capacity_);
    reads_ = writes_ = overflow_ = 0;
    inner_->Start(period);
  }
  void DoStop() noexcept override { inner_->Stop(); }
  void DoRead(double time, DeviceState* out) noexcept override {
    inner_->Read(time, out);
    ++reads_;
    if (samples_.size() < capacity_) {
      RecordedSample s;
      s.time = out->time;
      s.position = out->position;
      s.orientation = out->orientation;
      s.velocity = out->velocity;
      s.angular_velocity = out->angular_velocity;
      s.buttons = out->buttons;
      s.delivered = out->delivered;
      samples_.push_back(s);
    } else {
      ++overflow_;
    }
  }
  void DoWrite(const Wrench& wrench) noexcept override {
    ++writes_;
    if (!samples_.empty() && writes_ <= samples_.size()) samples_[writes_ - 1].commanded = wrench;
    inner_->Write(wrench);
  }
  void DoSetEnvironmentStiffness(double stiffness) noexcept override {
    inner_->SetEnvironmentStiffness(stiffness);
  }

 private:
  std::shared_ptr<Device> inner_;
  std::size_t capacity_;
  std::vector<RecordedSample> samples_;
  std::size_t reads_ = 0, writes_ = 0, overflow_ = 0;
};

std::string Slurp(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The paper scene with its `device:` and `part_motion:` blocks replaced by `device_yaml` (blocks
// at column 0): a device other than the paper's robot carries no load unless it says so.
fs::path SceneWithDevice(const fs::path& dir, const std::string& name,
                         const std::string& device_yaml) {
  std::istringstream in(Slurp(kPaperScene));
  std::ostringstream out;
  bool in_device = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("device:", 0) == 0 || line.rfind("part_motion:", 0) == 0) {
      in_device = true;
      continue;
    }
    if (in_device && (line.empty() || line[0] == ' ' || line[0] == '#')) continue;
    in_device = false;
    out << line << '\n';
  }
  out << device_yaml;
  const fs::path file = dir / (name + ".yaml");
  std::ofstream(file) << out.str();
  return file;
}

// One folder for every file the tests make; removed when the test program ends.
const fs::path& WorkDir() {
  static const fs::path dir = [] {
    const fs::path d =
        fs::temp_directory_path() / ("fitfeel-e2e-devices-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

class RemoveWorkDir : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(WorkDir(), ec);
  }
};
const auto* const kRemoveWorkDir = ::testing::AddGlobalTestEnvironment(new RemoveWorkDir);

struct DeviceRunResult {
  RunResult run;
  std::shared_ptr<ProbeDevice> probe;
  DeviceSpec spec;
};

// Loads the scene, wraps its device in the probe, shortens the run to `duration` and runs it on
// the virtual clock (a device that owns the clock runs on its own).
DeviceRunResult RunWithProbe(const fs::path& scene_file, double duration) {
  static PluginRegistry* registry = [] {
    auto* r = new PluginRegistry;
    r->LoadAll();
    return r;
  }();
  Scene scene = LoadScene(scene_file, *registry);
  scene.run.duration = duration;
  scene.run.clock = ClockMode::kVirtual;
  const auto capacity = static_cast<std::size_t>(std::llround(duration * scene.run.rate)) + 16;
  DeviceRunResult result;
  result.probe = std::make_shared<ProbeDevice>(scene.device, capacity);
  scene.device = result.probe;
  result.run = RunScene(std::move(scene), RunOptions{});
  result.spec = result.probe->spec();
  return result;
}

struct DeviceCase {
  std::string name;
  double duration = 0.0;  // s of run (the fake Phantom runs in real time)
  // Makes the scene file in `dir`; may run other devices first (the replay needs a recording).
  std::function<fs::path(const fs::path& dir)> make_scene;
  // What the device itself saw behind the Device interface, when it can tell (the fake HD
  // library counts frames and the largest force sent to the "hardware").
  std::function<void(const DeviceRunResult& run)> check_device_side;
};

void PrintTo(const DeviceCase& c, std::ostream* out) { *out << c.name; }

const fs::path kFakeHd = kBuildTree / "tests/fakehd/libHD.so";

// The fake HD library's counters, from the copy the Phantom plugin loaded.
FakeHdStats FakeHd() {
  FakeHdStats stats{};
  void* handle = ::dlopen(kFakeHd.c_str(), RTLD_NOW | RTLD_NOLOAD);
  EXPECT_NE(handle, nullptr) << "the Phantom plugin did not load " << kFakeHd;
  if (handle == nullptr) return stats;
  auto fn = reinterpret_cast<FakeHdStatsFn>(::dlsym(handle, "fakehd_stats"));
  EXPECT_NE(fn, nullptr);
  if (fn != nullptr) fn(&stats);
  ::dlclose(handle);
  return stats;
}

// The summary's physics: everything but what names the files and devices or measures this
// machine (prepare and tick times).
// What a run computed, without what depends on the device's identity or the machine: the
// replay states other limits and damping (finite ones, so the safety report's limits and the
// energy credited to the device's damping differ) and the same forces.
nlohmann::json SummaryPhysics(nlohmann::json summary) {
  for (const char* key :
       {"device", "scenario_file", "prepare_s", "ready_to_touch_ms", "tick_us", "wall_s"}) {
    summary.erase(key);
  }
  if (summary.contains("safety")) {
    for (const char* key : {"device_model", "peak_force_limit_N", "continuous_force_limit_N",
                            "energy_absorbed_J", "energy_created_J"}) {
      summary["safety"].erase(key);
    }
  }
  return summary;
}

// How the part moves under the shaft's 2 N weight (the scene's part_motion): quasi_static (the
// default: the stage settles the part where the contact carries the weight) or dynamic (the
// framework integrates the part's radial motion).
std::string PartMotionYaml(const std::string& radial) {
  return "part_motion:\n  radial: " + radial + "\n  radial_load: 2 N\n";
}

// The paper's robot: 10 mm/s, the shaft's 2 N weight, with the part's radial motion.
std::string SimulatedDevice(const std::string& radial = "quasi_static") {
  return "device:\n  plugin: fitfeel.device.simulated\n  speed: 10 mm/s\n" + PartMotionYaml(radial);
}

// A simulated run whose device stream the replay plays back, and its recording.
struct Recorded {
  DeviceRunResult run;
  fs::path recording;
};
const Recorded& SimulatedRecording(const std::string& radial) {
  static std::map<std::string, Recorded> recorded;
  auto it = recorded.find(radial);
  if (it == recorded.end()) {
    Recorded r;
    r.run = RunWithProbe(SceneWithDevice(WorkDir(), "recorded-" + radial, SimulatedDevice(radial)),
                         4.0);
    r.recording = WorkDir() / ("simulated-" + radial + ".rec");
    WriteRecording(r.recording, RecordingInfo{r.run.spec.model}, r.run.probe->samples());
    it = recorded.emplace(radial, std::move(r)).first;
  }
  return it->second;
}

std::string ReplayDevice(const std::string& radial) {
  return "device:\n  plugin: fitfeel.device.replay\n  file: '" +
         SimulatedRecording(radial).recording.string() + "'\n  model: PHANTOM Desktop\n" +
         PartMotionYaml(radial);
}

// Runs each case once; the tests below read the same run.
const DeviceRunResult& RunOf(const DeviceCase& c) {
  static std::map<std::string, DeviceRunResult> runs;
  auto it = runs.find(c.name);
  if (it == runs.end()) {
    it = runs.emplace(c.name, RunWithProbe(c.make_scene(WorkDir()), c.duration)).first;
  }
  return it->second;
}

class DeviceAgnosticTest : public ::testing::TestWithParam<DeviceCase> {};

TEST_P(DeviceAgnosticTest, TicksAndFiniteWrenches) {
  const DeviceCase& c = GetParam();
  const DeviceRunResult* r = nullptr;
  try {
    r = &RunOf(c);
  } catch (const UserError& e) {
    FAIL() << c.name << ": " << e.what();
  }
  const ProbeDevice& probe = *r->probe;
  const RunStats& stats = r->run.stats;
  const auto planned = static_cast<std::uint64_t>(std::llround(c.duration * 1000.0));

  // Tick count: as planned on the framework's (virtual) clock; a device that owns the clock
  // ends the run after `duration` of its own time, and a servo thread on a loaded machine may
  // serve fewer frames (lateness is reported, not asserted). One Read and one Write per tick,
  // every tick recorded.
  EXPECT_EQ(stats.planned_ticks, planned);
  if (r->probe->clock_owner() == ClockOwner::kFramework) {
    EXPECT_EQ(stats.ticks, planned);
  } else {
    EXPECT_GT(stats.ticks, 0u);
    EXPECT_LE(stats.ticks, planned);
  }
  EXPECT_EQ(probe.reads(), stats.ticks);
  EXPECT_EQ(probe.writes(), stats.ticks);
  EXPECT_EQ(probe.overflow(), 0u);
  EXPECT_EQ(r->run.summary.value("ticks", std::uint64_t{0}), stats.ticks);

  // Nothing non-finite crosses the device boundary, either way.
  std::size_t non_finite = 0;
  for (const RecordedSample& s : probe.samples()) {
    const bool finite = s.commanded.AllFinite() && s.position.allFinite() &&
                        s.velocity.allFinite() && std::isfinite(s.time);
    non_finite += finite ? 0 : 1;
  }
  EXPECT_EQ(non_finite, 0u) << c.name;
  if (c.check_device_side) c.check_device_side(*r);
}

TEST_P(DeviceAgnosticTest, NoWrenchAboveTheDeviceLimits) {
  const DeviceCase& c = GetParam();
  const DeviceRunResult* r = nullptr;
  try {
    r = &RunOf(c);
  } catch (const UserError& e) {
    FAIL() << c.name << ": " << e.what();
  }
  std::size_t above = 0;
  double largest = 0.0;
  for (const RecordedSample& s : r->probe->samples()) {
    if (!s.commanded.AllFinite()) continue;  // counted by TicksAndFiniteWrenches
    largest = std::max(largest, s.commanded.force.norm());
    if (s.commanded.force.norm() > r->spec.max_force * (1.0 + 1e-12)) ++above;
  }
  EXPECT_EQ(above, 0u) << c.name << ": " << above << " of " << r->probe->samples().size()
                       << " ticks wrote more than the device's peak force " << r->spec.max_force
                       << " N (" << r->spec.model << "); largest " << largest
                       << " N. Is the safety chain (framework/safety) wired between the stage "
                          "and Device::Write?";
}

// The replay of a simulated run's device stream gives the simulated run again, bit for bit: the
// same states read, the same wrenches written, the same summary. For both radial models of the
// simulated robot's part: what the device reports must all be in the recording, and the part's
// motion is the scene's, replayed as recorded.
class ReplayTest : public ::testing::TestWithParam<std::string> {};

TEST_P(ReplayTest, ReproducesTheRecordedRunBitForBit) {
  const std::string radial = GetParam();
  const Recorded& recorded = SimulatedRecording(radial);
  // The recording itself round-trips.
  const Recording back = ReadRecording(recorded.recording);
  ASSERT_EQ(back.samples.size(), recorded.run.probe->samples().size());

  // Replayed as the device it was recorded from: the simulated robot has no force limits,
  // imposes its position and is rendered directly (no coupling), so the replay says the same of
  // itself.
  const fs::path scene = SceneWithDevice(
      WorkDir(), "replay-bits-" + radial,
      "device:\n  plugin: fitfeel.device.replay\n  file: '" +
          SimulatedRecording(radial).recording.string() +
          "'\n  model: PHANTOM Desktop\n  spec: {max_force: 1e9 N, max_continuous_force: 1e9 N, "
          "max_stiffness: unlimited}\n"
          "safety:\n  coupling: direct\n" +
          PartMotionYaml(radial));
  const DeviceRunResult replay = RunWithProbe(scene, 4.0);
  const auto& a = recorded.run.probe->samples();
  const auto& b = replay.probe->samples();
  ASSERT_EQ(a.size(), b.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const bool same = a[i].time == b[i].time && a[i].position == b[i].position &&
                      a[i].velocity == b[i].velocity &&
                      a[i].commanded.force == b[i].commanded.force &&
                      a[i].commanded.torque == b[i].commanded.torque;
    if (!same && differing++ < 3) {
      ADD_FAILURE() << "tick " << i << " differs: position " << a[i].position.transpose() << " vs "
                    << b[i].position.transpose() << ", force " << a[i].commanded.force.transpose()
                    << " vs " << b[i].commanded.force.transpose();
    }
  }
  EXPECT_EQ(differing, 0u) << "of " << a.size() << " ticks (radial: " << radial
                           << "). Same states, other forces: does the device report something "
                              "the recording does not carry (DeviceState::load)?";
  EXPECT_EQ(SummaryPhysics(recorded.run.run.summary).dump(),
            SummaryPhysics(replay.run.summary).dump());
  EXPECT_EQ(recorded.run.run.stats.ticks, replay.run.stats.ticks);
}

INSTANTIATE_TEST_SUITE_P(Simulated, ReplayTest, ::testing::Values("dynamic", "quasi_static"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           return param.param;
                         });

void CheckFakeHd(const DeviceRunResult& run) {
  const FakeHdStats hd = FakeHd();
  // One servo frame per tick (the last frame, which sends zero force, may come after the run's
  // last tick), every frame closed, and the force the "hardware" got within its rating.
  EXPECT_GE(hd.frames, run.run.stats.ticks);
  EXPECT_LE(hd.frames, run.run.stats.ticks + 2);
  EXPECT_EQ(hd.frame_errors, 0u);
  EXPECT_TRUE(std::isfinite(hd.max_force));
  EXPECT_LE(hd.max_force, run.spec.max_force);
}

fs::path PhantomScene(const fs::path& dir) {
  ::setenv("FITFEEL_HD_LIBRARY", kFakeHd.c_str(), 1);
  ::setenv("FAKEHD_CALIBRATION", "ok", 1);
  return SceneWithDevice(dir, "phantom", "device:\n  plugin: fitfeel.device.phantom\n");
}

INSTANTIATE_TEST_SUITE_P(
    Devices, DeviceAgnosticTest,
    ::testing::Values(DeviceCase{"simulated", 4.0,
                                 [](const fs::path& dir) {
                                   return SceneWithDevice(dir, "simulated", SimulatedDevice());
                                 },
                                 nullptr},
                      DeviceCase{"simulated_dynamic", 4.0,
                                 [](const fs::path& dir) {
                                   return SceneWithDevice(dir, "simulated-dynamic",
                                                          SimulatedDevice("dynamic"));
                                 },
                                 nullptr},
                      DeviceCase{"replay", 4.0,
                                 [](const fs::path& dir) {
                                   return SceneWithDevice(dir, "replay", ReplayDevice("dynamic"));
                                 },
                                 nullptr},
                      DeviceCase{"phantom", 1.0, PhantomScene, CheckFakeHd}),
    [](const ::testing::TestParamInfo<DeviceCase>& param) { return param.param.name; });

// The Phantom end to end: the fake HD's stylus pushes the shaft straight into the bushing. The
// run must reach the constrained stage while the fake injects what real hardware does: a
// calibration that needs an update, a force error, a velocity error and warm motors; each must be
// survived and reported in summary.json.
TEST(PhantomE2e, ReachesTheConstrainedStageThroughInjectedFaults) {
  const fs::path dir = WorkDir();
  ::setenv("FITFEEL_HD_LIBRARY", (kBuildTree / "tests/fakehd/libHD.so").c_str(), 1);
  // The stylus starts 20 mm before the entrance (the default frame) and pushes in at 20 mm/s, 0.1
  // mm off the axis: at the entrance after 1000 frames, 10 mm in after 1500, where it stays. The
  // fake's clock counts servo periods, so a busy machine changes none of the counts below.
  ::setenv("FAKEHD_PATH", "insert", 1);
  ::setenv("FAKEHD_CALIBRATION", "update", 1);
  ::setenv("FAKEHD_FORCE_ERROR_FRAME", "1050", 1);
  ::setenv("FAKEHD_VELOCITY_ERROR_FRAME", "1200", 1);
  ::setenv("FAKEHD_WARM_FRAME", "1350", 1);
  PluginRegistry registry;
  registry.LoadAll();
  Scene scene = LoadScene(
      SceneWithDevice(dir, "phantom-insert",
                      "device:\n  plugin: fitfeel.device.phantom\n  model: PHANTOM Desktop\n"),
      registry);
  scene.run.duration = 2.5;
  RunOptions options;
  options.out_dir = dir / "out";
  const RunResult result = RunScene(std::move(scene), options);

  std::ifstream summary_file(result.paths.summary);
  const nlohmann::json summary = nlohmann::json::parse(summary_file);
  const nlohmann::json& device = summary.at("device_report");
  std::printf("%s\n", device.dump(2).c_str());
  std::printf(
      "ticks %llu, constrained %llu\n",
      static_cast<unsigned long long>(summary.at("ticks").get<std::uint64_t>()),
      static_cast<unsigned long long>(summary.at("constrained_ticks").get<std::uint64_t>()));
  // The run went on to its end and most of its second half was constrained.
  EXPECT_FALSE(device.at("stopped_on_faults").get<bool>());
  EXPECT_EQ(summary.at("ticks").get<double>(), 2500.0);
  EXPECT_GT(summary.at("constrained_ticks").get<double>(),
            0.35 * summary.at("ticks").get<double>());
  // Each fault is reported.
  EXPECT_EQ(device.at("calibration"), "updated (auto)");
  EXPECT_EQ(device.at("calibration_updates"), 1);
  EXPECT_EQ(device.at("force_errors").get<int>(), 1);
  EXPECT_EQ(device.at("velocity_errors"), 1);
  EXPECT_EQ(device.at("warm_motor_errors").get<int>(), 1);
  EXPECT_GT(device.at("zeroed_ticks").get<int>(), 0);
  EXPECT_GT(device.at("ramped_ticks").get<int>(), 0);
  EXPECT_EQ(device.at("update_rate_Hz"), 1000.0);
  // Within the driver's peak.
  EXPECT_LE(device.at("max_force_sent_N").get<double>(), 7.9);
  for (const char* name : {"FAKEHD_PATH", "FAKEHD_CALIBRATION", "FAKEHD_FORCE_ERROR_FRAME",
                           "FAKEHD_VELOCITY_ERROR_FRAME", "FAKEHD_WARM_FRAME"}) {
    ::unsetenv(name);
  }
}

}  // namespace
}  // namespace fitfeel
