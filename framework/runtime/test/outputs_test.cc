#include "framework/runtime/outputs.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "framework/core/error.h"
#include "framework/runtime/run.h"
#include "framework/runtime/test/fake_scene.h"
#include "framework/runtime/test/output_files.h"
// After the framework headers: <signal.h> (pulled in by gtest) defines si_value as a macro.
#include <gtest/gtest.h>

namespace fitfeel {
namespace {

namespace fs = std::filesystem;

fs::path OutputsDir(const std::string& name) { return testing::FreshDir("outputs", name); }
using testing::Lines;

// Drops the tick_us column (7th), the only measured one.
std::vector<std::string> WithoutTickTime(std::vector<std::string> lines) {
  for (auto& line : lines) {
    std::size_t pos = 0;
    for (int i = 0; i < 6; ++i) pos = line.find(',', pos) + 1;
    const std::size_t end = line.find(',', pos);
    line.erase(pos, end - pos);
  }
  return lines;
}

TEST(OutputsTest, RunWritesTheContractsFilesAndNothingElse) {
  const fs::path dir = OutputsDir("run");
  RunOptions options;
  options.out_dir = dir;
  const RunResult result = RunScene(testing::MakeFakeScene(5, 0.5), options);
  EXPECT_EQ(result.paths.trace, dir / "trace.csv");
  EXPECT_EQ(result.paths.summary, dir / "summary.json");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 2u);  // no temporaries left

  const auto lines = Lines(dir / "trace.csv");
  ASSERT_EQ(lines.size(), 501u);
  EXPECT_EQ(lines[0].rfind("t_s,stage,depth_mm,fx_N,fy_N,fz_N,tick_us", 0), 0u);
  EXPECT_EQ(lines[1].rfind("0,positioning,-1,0,0,0,", 0), 0u);
  EXPECT_NE(lines[500].find(",constrained,"), std::string::npos);

  std::ifstream in(dir / "summary.json");
  const auto summary = nlohmann::json::parse(in);
  for (const char* key :
       {"scenario", "scenario_file", "seed", "law", "ticks", "deadline_misses", "tick_us",
        "axial_resistance_N", "radial_resistance_N", "prepare_s", "grid"}) {
    EXPECT_TRUE(summary.contains(key)) << key;
  }
  EXPECT_EQ(summary["scenario"], "fake");
  EXPECT_EQ(summary["seed"], 5);
  EXPECT_EQ(summary["ticks"], 500);
  EXPECT_EQ(summary["constrained_ticks"], 399);  // ticks 101..499
  EXPECT_TRUE(summary["tick_us"].contains("p99"));
  // Unsettled constrained ticks (four in five here) evaluate the contact at the pose, and once
  // more for the radial stiffness where the law pushes; positioning ticks none.
  EXPECT_GE(summary["contact_evaluations"]["p50"].get<double>(), 1.0);
  EXPECT_EQ(summary["contact_evaluations"]["max"], 2.0);
  const auto& axial = summary["axial_resistance_N"];
  EXPECT_LE(axial["min"].get<double>(), axial["mean"].get<double>());
  EXPECT_LE(axial["mean"].get<double>(), axial["max"].get<double>());
  EXPECT_GT(axial["max"].get<double>(), 0.0);
  EXPECT_EQ(summary["grid"]["inner"]["columns"], 8);
  EXPECT_EQ(result.summary, summary);

  // The same seed again gives the same file except for the measured compute time.
  const fs::path again = OutputsDir("again");
  options.out_dir = again;
  RunScene(testing::MakeFakeScene(5, 0.5), options);
  EXPECT_EQ(WithoutTickTime(Lines(dir / "trace.csv")), WithoutTickTime(Lines(again / "trace.csv")));
  fs::remove_all(dir);
  fs::remove_all(again);
}

TEST(OutputsTest, TraceCarriesTheDeviceWrenchAndSummaryTheSafetyChain) {
  const fs::path dir = OutputsDir("safety");
  RunOptions options;
  options.out_dir = dir;
  const RunResult result = RunScene(testing::MakeFakeScene(5, 0.5), options);
  const auto lines = Lines(dir / "trace.csv");
  const std::string tail =
      ",guard_fault,dev_fx_N,dev_fy_N,dev_fz_N,dev_tx_Nm,dev_ty_Nm,dev_tz_Nm,offset_x_um,"
      "offset_z_um,elastic_utilisation,yielding,device_fault,prepare_held_mm";
  ASSERT_GE(lines[0].size(), tail.size());
  EXPECT_EQ(lines[0].substr(lines[0].size() - tail.size()), tail);
  const auto columns = std::count(lines[0].begin(), lines[0].end(), ',');
  for (const auto& line : lines) ASSERT_EQ(std::count(line.begin(), line.end(), ','), columns);
  const auto& safety = result.summary["safety"];
  for (const char* key : {"force_scale", "coupling", "faults", "saturated_ticks",
                          "energy_created_J", "max_physical_force_N"}) {
    EXPECT_TRUE(safety.contains(key)) << key;
  }
  EXPECT_EQ(safety["force_scale"], 1.0);
  EXPECT_EQ(safety["coupling"]["mode"], "direct");  // the fake device has no limits
  EXPECT_TRUE(safety["peak_force_limit_N"].is_null());
  EXPECT_EQ(safety["faults"], 0);
  EXPECT_GE(safety["energy_created_J"].get<double>(), 0.0);
  fs::remove_all(dir);
}

TEST(OutputsTest, RecordingIsWrittenOnRequestAndReadsBack) {
  const fs::path dir = OutputsDir("recording");
  RunOptions options;
  options.out_dir = dir;
  Scene scene = testing::MakeFakeScene(5, 0.5);
  scene.run.write_recording = true;
  const RunResult result = RunScene(std::move(scene), options);
  EXPECT_EQ(result.paths.recording, dir / "recording.csv");
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 3u);  // trace, summary, recording; no temporaries
  const Recording recording = ReadRecording(dir / "recording.csv");
  EXPECT_EQ(recording.info.device_model, "fake unlimited device");
  ASSERT_EQ(recording.samples.size(), 500u);
  const auto lines = Lines(dir / "trace.csv");
  for (std::size_t k = 0; k < 500; ++k) {
    ASSERT_EQ(recording.samples[k].time, static_cast<double>(k) / 1000.0);
  }
  // The device moved at 10 mm/s along the axis (KinematicDevice in the fake scene).
  EXPECT_NEAR(recording.samples[499].position.y() - recording.samples[0].position.y(), 499 * 1e-5,
              1e-12);
  fs::remove_all(dir);
}

TEST(OutputsTest, AFailedPrepareCreatesNoFolder) {
  const fs::path dir = OutputsDir("prepare");
  RunOptions options;
  options.out_dir = dir;
  auto failing = std::make_shared<testing::FakeSurface>(false, true);
  EXPECT_THROW(RunScene(testing::MakeFakeScene(1, 0.5, nullptr, failing), options), UserError);
  EXPECT_FALSE(fs::exists(dir));
}

TEST(OutputsTest, AFailedRenameLeavesNoFileBehind) {
  const fs::path dir = OutputsDir("rename");
  // summary.json is a non-empty folder: the trace is written and renamed, then the summary's
  // rename fails, and the trace must go again.
  fs::create_directories(dir / "summary.json" / "blocker");
  std::vector<TickRecord> trace(3);
  RunStats stats;
  stats.ticks = 3;
  EXPECT_THROW(WriteOutputs(dir, RunInfo{}, trace, stats), UserError);
  EXPECT_FALSE(fs::exists(dir / "trace.csv"));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++entries;
  EXPECT_EQ(entries, 1u);  // only the blocker folder
  fs::remove_all(dir);
}

TEST(OutputsTest, AnUnwritableFolderIsAUserErrorAndCreatesNothing) {
  const fs::path dir = OutputsDir("file");
  { std::ofstream(dir.string()) << "not a folder"; }
  EXPECT_THROW(WriteOutputs(dir / "sub", RunInfo{}, {}, RunStats{}), UserError);
  EXPECT_THROW(WriteOutputs(dir, RunInfo{}, {}, RunStats{}), UserError);
  fs::remove(dir);
}

TEST(OutputsTest, SummaryStatisticsAreOverTheConstrainedStage) {
  std::vector<TickRecord> trace(4);
  trace[0].stage = StageId::kPositioning;
  trace[0].wrench.force = Eigen::Vector3d(100.0, 100.0, 100.0);  // ignored
  trace[1].stage = trace[2].stage = trace[3].stage = StageId::kConstrained;
  trace[1].wrench.force = Eigen::Vector3d(3.0, -1.0, 4.0);
  trace[2].wrench.force = Eigen::Vector3d(0.0, -2.0, 0.0);
  trace[3].wrench.force = Eigen::Vector3d(0.0, 3.0, -2.0);
  RunInfo info;
  info.rotational = true;
  const auto j = MakeSummary(info, trace, RunStats{});
  EXPECT_DOUBLE_EQ(j["axial_resistance_N"]["mean"].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(j["axial_resistance_N"]["min"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(j["axial_resistance_N"]["max"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(j["fy_N"]["min"].get<double>(), -2.0);
  EXPECT_DOUBLE_EQ(j["radial_resistance_N"]["mean"].get<double>(), 7.0 / 3.0);
  EXPECT_DOUBLE_EQ(j["radial_resistance_N"]["max"].get<double>(), 5.0);
  EXPECT_TRUE(j.contains("torque_Nm"));
  // No constrained tick: null statistics, not zeros.
  const auto none = MakeSummary(RunInfo{}, std::vector<TickRecord>(2), RunStats{});
  EXPECT_TRUE(none["axial_resistance_N"]["mean"].is_null());
  EXPECT_FALSE(none.contains("torque_Nm"));
}

TEST(OutputsTest, TraceFlagsYieldingAndTheSummarySaysWhereAndByHowMuch) {
  std::vector<TickRecord> trace(4);
  for (auto& r : trace) r.stage = StageId::kConstrained;
  trace[0].stage = StageId::kPositioning;
  trace[0].elastic = {5.0, 1};  // not constrained: ignored
  trace[1].elastic = {0.5, 1};
  trace[2].elastic = {1.25, 2};
  trace[2].pose.depth = 3e-3;
  trace[2].time = 0.002;
  trace[3].elastic = {1.1, 1};
  const auto j = MakeSummary(RunInfo{}, trace, RunStats{});
  const auto& e = j["elastic_limit"];
  EXPECT_EQ(e["yielding_ticks"], 2);
  EXPECT_DOUBLE_EQ(e["max_utilisation"].get<double>(), 1.25);
  EXPECT_EQ(e["part"], "inner");
  EXPECT_DOUBLE_EQ(e["at_depth_mm"].get<double>(), 3.0);
  EXPECT_DOUBLE_EQ(e["at_t_s"].get<double>(), 0.002);
  EXPECT_NEAR(e["excess_percent"].get<double>(), 25.0, 1e-12);
  const std::string row = TraceRow(trace[2]);
  EXPECT_EQ(row.substr(row.size() - 11), ",1.25,1,0,0");  // then device_fault, prepare_held_mm
  const std::string elastic = TraceRow(trace[1]);
  EXPECT_EQ(elastic.substr(elastic.size() - 10), ",0.5,0,0,0");
  // Nothing checked (no yield strength, or a law without a check): null, not zero.
  EXPECT_TRUE(MakeSummary(RunInfo{}, std::vector<TickRecord>(2),
                          RunStats{})["elastic_limit"]["max_utilisation"]
                  .is_null());
}

}  // namespace
}  // namespace fitfeel
