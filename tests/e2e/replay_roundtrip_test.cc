// Record and replay end to end through the real CLI and plugins: a run of a simulated hand writes
// recording.csv; the replay device playing it against the same scene and seed gives the same
// trace bit for bit (every column but tick_us, a measurement of this machine).
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include "framework/testing/cli_runner.h"
#include "framework/testing/source_tree.h"

namespace {

namespace fs = std::filesystem;
using ::fitfeel::test_support::CliResult;
using ::fitfeel::test_support::ReadText;
using ::fitfeel::test_support::RunFitfeelInSourceTree;

using ::fitfeel::test_support::kSourceTree;

void WriteText(const fs::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
}

// Every row of a trace with the tick_us column (the 7th) removed.
std::vector<std::string> TracePhysics(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> rows;
  for (std::string line; std::getline(in, line);) {
    std::size_t pos = 0;
    for (int i = 0; i < 6; ++i) pos = line.find(',', pos) + 1;
    line.erase(pos, line.find(',', pos) - pos);
    rows.push_back(line);
  }
  return rows;
}

// The paper's case-1 scene (parts, model) with the given device, safety and run sections.
std::string CaseOneWith(const std::string& tail) {
  const std::string paper = ReadText(kSourceTree / "scenarios" / "paper-case1-h7js6.yaml");
  const std::size_t device = paper.find("\ndevice:");
  EXPECT_NE(device, std::string::npos);
  return paper.substr(0, device + 1) + tail;
}

class ReplayRoundTrip : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fitfeel-replay-e2e-" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

// A hand (mass, spring and damper to a moving target) pushes the shaft 14 mm into the bushing in
// 1.5 s: its motion depends on what the device renders, so the recording is not a straight line.
constexpr const char* kHand = R"(device:
  plugin: fitfeel.device.simulated
  mode: scripted
  hand: {mass: 0.5 kg, stiffness: 2000 N/m, damping: 20 N*s/m}
  waypoints:
    - {time: 0 s, position: [0 mm, -1 mm, 0 mm]}
    - {time: 1.5 s, position: [0 mm, 14 mm, 0 mm]}
)";

constexpr const char* kRun = R"(run:
  rate: 1000 Hz
  duration: 1.5 s
  seed: 3
  clock: virtual
)";

// Records a run of the hand with `safety` (may be empty), replays it with `replay_device` and
// `safety`, and checks the traces agree bit for bit. Returns the recorded run's summary.
nlohmann::json RoundTrip(const fs::path& dir, const std::string& safety,
                         const std::string& replay_device) {
  const fs::path recorded = dir / "recorded";
  WriteText(dir / "record.yaml", CaseOneWith(std::string(kHand) + safety + kRun +
                                             "  outputs: [trace, summary, recording]\n"));
  const CliResult a = RunFitfeelInSourceTree("run '" + (dir / "record.yaml").string() +
                                             "' --out '" + recorded.string() + "'");
  EXPECT_EQ(a.exit_code, 0) << a.out;
  EXPECT_TRUE(fs::exists(recorded / "recording.csv")) << a.out;
  EXPECT_NE(a.out.find((recorded / "recording.csv").string()), std::string::npos) << a.out;
  EXPECT_NE(a.out.find("safety"), std::string::npos) << a.out;

  fs::copy_file(recorded / "recording.csv", dir / "hand.rec", fs::copy_options::overwrite_existing);
  WriteText(dir / "replay.yaml",
            CaseOneWith(replay_device + safety + kRun + "  outputs: [trace, summary]\n"));
  const fs::path replayed = dir / "replayed";
  const CliResult b = RunFitfeelInSourceTree("run '" + (dir / "replay.yaml").string() +
                                             "' --out '" + replayed.string() + "'");
  EXPECT_EQ(b.exit_code, 0) << b.out;

  const auto original = TracePhysics(recorded / "trace.csv");
  const auto replay = TracePhysics(replayed / "trace.csv");
  EXPECT_EQ(original.size(), 1501u);
  EXPECT_EQ(replay.size(), original.size());
  for (std::size_t k = 0; k < std::min(original.size(), replay.size()); ++k) {
    if (replay[k] != original[k]) {
      ADD_FAILURE() << "row " << k << "\n  recorded " << original[k] << "\n  replayed "
                    << replay[k];
      break;
    }
  }
  std::ifstream in(recorded / "summary.json");
  return nlohmann::json::parse(in);
}

// The replay device is a desktop device (limits, default coupling): the scene says how the
// recorded run rendered and gives limits the recorded forces stay under, and the stiffness the
// hand renders (2 b / T: 20 N*s/m at 1 kHz), which sets the god object's spring.
constexpr const char* kReplay = R"(device:
  plugin: fitfeel.device.replay
  file: hand.rec
  model: PHANTOM Desktop
  spec: {max_force: 1e9 N, max_continuous_force: 1e9 N, max_stiffness: 40000 N/m}
)";

TEST_F(ReplayRoundTrip, ReplayingARecordingGivesTheSameTraceBitForBit) {
  // The hand renders directly (no safety section: a device without limits passes through); the
  // replay is told so.
  const nlohmann::json summary =
      RoundTrip(dir_, "", std::string(kReplay) + "safety:\n  coupling: direct\n");
  // Not a trivial equality: the hand met the fit.
  EXPECT_GT(summary["constrained_ticks"].get<int>(), 100);
  EXPECT_GT(summary["axial_resistance_N"]["max"].get<double>(), 0.0);
  EXPECT_EQ(summary["safety"]["force_scale"].get<double>(), 1.0);
  EXPECT_EQ(summary["safety"]["coupling"]["mode"], "direct");

  // A recording cut short is refused with its line, and nothing is written.
  std::string text = ReadText(dir_ / "hand.rec");
  text.resize(text.size() / 2);
  text.resize(text.rfind('\n') + 1);
  WriteText(dir_ / "hand.rec", text);
  const fs::path refused = dir_ / "refused";
  const CliResult c = RunFitfeelInSourceTree("run '" + (dir_ / "replay.yaml").string() +
                                             "' --out '" + refused.string() + "'");
  EXPECT_EQ(c.exit_code, 2) << c.out;
  EXPECT_NE(c.out.find("hand.rec:"), std::string::npos) << c.out;
  EXPECT_FALSE(fs::exists(refused));
}

// Through the virtual coupling at a tenth of the physical force: the law acts on the proxy, which
// the replay rebuilds from the same handle motion. The replayed device's damping is the hand's
// (20 N*s/m), so the coupling gains chosen from the spec are the same.
TEST_F(ReplayRoundTrip, ACoupledRunReplaysBitForBitToo) {
  const std::string safety = "safety:\n  coupling: spring_damper\n  force_scale: 0.1\n";
  const nlohmann::json summary =
      RoundTrip(dir_, safety,
                std::string(kReplay).replace(std::string(kReplay).find("}\n"), 2,
                                             ", damping: 20 N*s/m}\n"));
  EXPECT_GT(summary["constrained_ticks"].get<int>(), 100);
  EXPECT_EQ(summary["safety"]["coupling"]["mode"], "spring_damper");
  EXPECT_EQ(summary["safety"]["force_scale"].get<double>(), 0.1);
  EXPECT_GT(summary["safety"]["coupling"]["stiffness_N_per_m"].get<double>(), 0.0);
}

}  // namespace
