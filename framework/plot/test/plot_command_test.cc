// Runs the real `fitfeel plot` binary: bad input exits 2 with a clear message on stderr and writes
// no image; good input writes the images it names.
#include <filesystem>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/plot/test/test_support.h"
#include "framework/testing/cli_runner.h"

namespace fitfeel::plot {
namespace {

namespace fs = std::filesystem;
using test_support::CliOptions;
using test_support::CliResult;
using ::testing::HasSubstr;
using testing::ScratchDir;

// Runs `fitfeel plot <args>` in `cwd`, capturing its output.
CliResult Fitfeel(const std::vector<std::string>& args, const fs::path& cwd) {
  return test_support::RunFitfeel("plot " + test_support::ShellWords(args), CliOptions().In(cwd));
}

bool NoImages(const fs::path& dir) {
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const auto ext = entry.path().extension();
    if (ext == ".png" || ext == ".svg") return false;
  }
  return true;
}

TEST(PlotCommand, MissingRunFolderExitsTwo) {
  ScratchDir dir;
  const CliResult r = Fitfeel({"trace", "no-such-run", "-o", "chart.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("run folder 'no-such-run' does not exist"));
  EXPECT_TRUE(NoImages(dir.path()));
}

TEST(PlotCommand, TraceWithoutNeededColumnsExitsTwo) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "run", "s", "gps", 1.0);
  testing::WriteFile(dir.path() / "run" / "trace.csv", "t_s,stage,depth_mm\n0,constrained,0\n");
  const CliResult r = Fitfeel({"trace", "run", "-o", "chart"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("header lacks the column(s) fx_N, fy_N, fz_N"));
  EXPECT_TRUE(NoImages(dir.path()));
}

TEST(PlotCommand, UnknownExtensionExitsTwo) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "run", "s", "gps", 1.0);
  const CliResult r = Fitfeel({"trace", "run", "-o", "chart.jpeg"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("has the extension '.jpeg'; expected .png, .svg"));
  EXPECT_TRUE(NoImages(dir.path()));
}

TEST(PlotCommand, DepthOutsideTheRunExitsTwo) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "run", "s", "gps", 1.0);  // constrained from 0 to 17.9 mm
  const CliResult r = Fitfeel({"pressure", "run", "--depth", "18.5", "-o", "p.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("depth 18.5 mm is outside the run's constrained depth range "
                               "0.000 mm to 17.900 mm"));
  EXPECT_TRUE(NoImages(dir.path()));
}

TEST(PlotCommand, PressureNeedsTheRunsScenarioFile) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "run", "s", "gps", 1.0);  // names scenarios/s.yaml
  const CliResult r = Fitfeel({"pressure", "run", "--depth", "5", "-o", "p.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("scenario file 'scenarios/s.yaml' was not found"));
}

TEST(PlotCommand, SmsOfAMissingScenarioExitsTwo) {
  ScratchDir dir;
  const CliResult r = Fitfeel({"sms", "absent.yaml", "-o", "sms.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("absent.yaml"));
  EXPECT_TRUE(NoImages(dir.path()));
}

// The real cylindrical surface and simulated device plugins on the paper's scenario. They are part
// of the build once the cylindrical generator and the runtime have landed; before that this build
// has nothing to load the scenario with.
const fs::path kPlugins = fs::path(FITFEEL_TEST_BUILD_DIR) / "plugins";
bool HaveCase1Plugins() {
  return fs::exists(kPlugins / "libfitfeel_surface_cylindrical.so") &&
         fs::exists(kPlugins / "libfitfeel_device_simulated.so");
}
const fs::path kCase1 = fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / "paper-case1-h7js6.yaml";

TEST(PlotCommand, SmsOfThePaperScenarioWritesPngAndSvg) {
  FITFEEL_REQUIRE_GNUPLOT();
  if (!HaveCase1Plugins()) GTEST_SKIP() << "no cylindrical surface or simulated device plugin";
  ScratchDir dir;
  const CliResult r = Fitfeel({"sms", kCase1.string(), "-o", "sms"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(testing::IsPng(dir.path() / "sms.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "sms.svg"));
  const CliResult one =
      Fitfeel({"sms", kCase1.string(), "--part", "shaft", "-o", "shaft.png"}, dir.path());
  EXPECT_EQ(one.exit_code, 0) << one.err;
  EXPECT_TRUE(testing::IsPng(dir.path() / "shaft.png"));
  const CliResult bad =
      Fitfeel({"sms", kCase1.string(), "--part", "gear", "-o", "g.png"}, dir.path());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_THAT(bad.err, HasSubstr("no part 'gear'"));
}

TEST(PlotCommand, TraceWritesPngAndSvg) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  testing::WriteRun(dir.path() / "a", "paper-case1-h7js6", "gps", 12.0);
  testing::WriteRun(dir.path() / "b", "paper-case1-h7g6", "gps", 0.4);
  const CliResult r = Fitfeel({"trace", "a", "b", "--log", "-o", "trace"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(testing::IsPng(dir.path() / "trace.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "trace.svg"));
  EXPECT_THAT(r.out, HasSubstr("wrote trace.png"));
}

TEST(PlotCommand, TraceTorqueDrawsAScrewsRunAndRefusesAFits) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  testing::WriteScrewRun(dir.path() / "bolt");
  const CliResult r = Fitfeel({"trace", "bolt", "--torque", "-o", "torque"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(testing::IsPng(dir.path() / "torque.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "torque.svg"));
  testing::WriteRun(dir.path() / "fit", "paper-case1-h7js6", "gps", 12.0);
  const CliResult fit = Fitfeel({"trace", "fit", "--torque", "-o", "fit.png"}, dir.path());
  EXPECT_EQ(fit.exit_code, 2);
  EXPECT_THAT(fit.err, HasSubstr("has no torque_Nm"));
  EXPECT_FALSE(fs::exists(dir.path() / "fit.png"));
  // The torque's axes are linear: --log belongs to the resistance chart.
  EXPECT_EQ(Fitfeel({"trace", "bolt", "--torque", "--log", "-o", "t.png"}, dir.path()).exit_code,
            2);
}

// A run folder whose summary records the perceptual mapping of a Touch and the run's means.
void WriteMappedRun(const fs::path& dir, const std::string& scenario, double scene_N,
                    double device_N) {
  fs::create_directories(dir);
  testing::WriteFile(
      dir / "summary.json",
      "{\"scenario\": \"" + scenario +
          "\", \"axial_resistance_N\": {\"mean\": " + std::to_string(scene_N) +
          "}, \"delivered_force_N\": {\"mean\": " + std::to_string(device_N) +
          "}, \"safety\": {\"device_model\": \"Touch\", \"force_mapping\": {\"kind\": "
          "\"perceptual\", \"knee_N\": 0.1, \"exponent\": 0.197, \"scene_top_N\": 20000, "
          "\"device_top_N\": 1.1068}}}\n");
}

TEST(PlotCommand, MappingDrawsTheCurveAndTheRuns) {
  FITFEEL_REQUIRE_GNUPLOT();
  ScratchDir dir;
  // Two runs at one place share a label.
  WriteMappedRun(dir.path() / "g6", "fits-20mm-h7g6", 0.2998, 0.1808);
  WriteMappedRun(dir.path() / "h6", "fits-20mm-h7h6", 0.2998, 0.1808);
  WriteMappedRun(dir.path() / "s6", "fits-20mm-h7s6", 12614.0, 0.991);
  const CliResult r = Fitfeel({"mapping", "g6", "h6", "s6", "-o", "mapping"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(testing::IsPng(dir.path() / "mapping.png"));
  EXPECT_TRUE(testing::IsSvg(dir.path() / "mapping.svg"));
  const std::string svg = testing::ReadFile(dir.path() / "mapping.svg");
  EXPECT_THAT(svg, HasSubstr("fits-20mm-h7g6, fits-20mm-h7h6"));
  EXPECT_THAT(svg, HasSubstr("fits-20mm-h7s6"));
  EXPECT_THAT(r.out, HasSubstr("wrote mapping.png"));
}

TEST(PlotCommand, MappingRefusesARunWithoutOneExitsTwo) {
  ScratchDir dir;
  testing::WriteRun(dir.path() / "old", "s", "gps", 1.0);  // a summary with no safety section
  const CliResult r = Fitfeel({"mapping", "old", "-o", "m.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("old/summary.json: safety.force_mapping: the run's summary records "
                               "no force mapping"));
  EXPECT_TRUE(NoImages(dir.path()));
  const CliResult absent = Fitfeel({"mapping", "nowhere", "-o", "m.png"}, dir.path());
  EXPECT_EQ(absent.exit_code, 2);
  EXPECT_THAT(absent.err, HasSubstr("run folder 'nowhere' does not exist"));
}

}  // namespace
}  // namespace fitfeel::plot
