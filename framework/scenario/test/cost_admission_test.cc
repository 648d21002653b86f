// Every command that loads a scene admits its cost as `run` does: a grid of 4 million cells per
// part is refused at once (exit code 2, the loader's message, nothing written) by each of them,
// tradeoff's own grids and durations included; `validate` prints the run's output size and, with
// `run`, refuses outputs over the large-output threshold unless --allow-large.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/plugin/registry.h"
#include "framework/scenario/scene.h"
#include "framework/testing/cli_runner.h"
#include "framework/testing/source_tree.h"
#include "framework/tradeoff/grid_ladder.h"
#include "framework/tradeoff/tradeoff_study.h"

namespace {

namespace fs = std::filesystem;
using ::fitfeel::test_support::CliOptions;
using ::fitfeel::test_support::CliResult;
using ::fitfeel::test_support::FitfeelBinary;
using ::fitfeel::test_support::ReadText;
using ::fitfeel::test_support::RunFitfeel;
using ::fitfeel::test_support::ShellQuote;
using ::fitfeel::test_support::ShippedScenario;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kLargeScene =
    "model.resolution: expected a scene that prepares within 1 GiB and 30 s, or --allow-large to "
    "run it anyway, found a map: 8e+06 cells, ";

// A folder of this process and test: the scenario written into it, and the commands run in an
// empty folder `work` beside it, checked for what they leave.
class CostAdmission : public ::testing::Test {
 protected:
  CostAdmission()
      : dir_(fitfeel::test_support::EmptyTestFolder("cost-admission")), work_(dir_ / "work") {
    fs::create_directories(work_);
  }
  ~CostAdmission() override { fs::remove_all(dir_); }

  // The paper scene with each `from` replaced by its `to`.
  fs::path PaperSceneWith(const std::vector<std::pair<std::string, std::string>>& edits) const {
    std::string text = ReadText(ShippedScenario("paper-case1-h7js6.yaml"));
    for (const auto& [from, to] : edits) {
      const std::size_t at = text.find(from);
      EXPECT_NE(at, std::string::npos) << from;
      if (at != std::string::npos) text.replace(at, from.size(), to);
    }
    const fs::path file = dir_ / "scene.yaml";
    std::ofstream(file) << text;
    return file;
  }

  CliResult Fitfeel(const std::string& arguments) const {
    return RunFitfeel(arguments, CliOptions().In(work_));
  }

  fs::path dir_;
  fs::path work_;
};

TEST_F(CostAdmission, EveryCommandRefusesAFourMillionCellGridBeforeComputingAnything) {
  if (!fs::exists(FitfeelBinary())) GTEST_SKIP() << "build the fitfeel target first";
  const std::string scene = ShellQuote(
      PaperSceneWith({{"resolution: {rows: 40, columns: 360}",
                       "resolution: {rows: 2000, columns: 2000}"}})
          .string());
  const std::pair<std::string, std::string> commands[] = {
      {"validate", scene},
      {"run", scene + " --out out"},
      {"sms", scene},
      {"plot sms", scene + " -o chart.png"},
      {"study", scene + " --pairs 2 --out study"},
      {"tradeoff", scene + " -o ladder --resolutions 8x36"},
      {"view", scene + " --port 0"}};
  for (const auto& [command, arguments] : commands) {
    const CliResult r = Fitfeel(command + " " + arguments);
    EXPECT_EQ(r.exit_code, 2) << command << "\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr((dir_ / "scene.yaml").string() + ":48:15: " + kLargeScene))
        << command;
    EXPECT_TRUE(fs::is_empty(work_)) << command << " left files behind";
    // The refusal names a flag the command takes.
    EXPECT_THAT(Fitfeel(command + " --help").out, HasSubstr("--allow-large")) << command;
  }
  // tradeoff's own grids: the shipped scene at a grid of the user's.
  const CliResult r = Fitfeel("tradeoff " + ShellQuote(ShippedScenario("paper-case1-h7js6.yaml")) +
                              " -o ladder --resolutions 8x36,2000x2000");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("fitfeel: error: tradeoff: --resolutions: expected a scene that "
                               "prepares within 1 GiB and 30 s, or --allow-large to run it anyway, "
                               "found 2000x2000: 8e+06 cells, "));
  EXPECT_TRUE(fs::is_empty(work_));
}

TEST_F(CostAdmission, TradeoffAdmitsItsDurationAndTheTracesItHolds) {
  if (!fs::exists(FitfeelBinary())) GTEST_SKIP() << "build the fitfeel target first";
  const std::string scene = ShellQuote(ShippedScenario("paper-case1-h7js6.yaml"));
  // Each run's trace: 2e7 ticks at 1 kHz.
  CliResult r = Fitfeel("tradeoff " + scene + " -o ladder --resolutions 8x36 --seeds 1 "
                        "--duration '20000 s'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("fitfeel: error: tradeoff: --duration: expected a run whose "
                               "trace.csv and recording.csv stay within 4 GiB, or --allow-large "
                               "to write them anyway, found 2e+04 s: 6.71 GiB of output (2e+07 "
                               "trace rows of about 360 B)\n"));
  // The axial traces of every run, held for the comparison: 1000 x 2e5 doubles.
  r = Fitfeel("tradeoff " + scene + " -o ladder --resolutions 8x36 --seeds 1000 "
              "--duration '200 s'");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("fitfeel: error: tradeoff: --seeds: expected a study whose axial "
                               "traces (8 B a tick of every run) are held within 1 GiB, or "
                               "--allow-large to run it anyway, found 1 grid x 1000 seeds x "
                               "2e+05 ticks: 1.49 GiB\n"));
  EXPECT_TRUE(fs::is_empty(work_));
}

TEST_F(CostAdmission, ValidatePrintsTheOutputSizeAndRunRefusesOutputsOverTheThreshold) {
  if (!fs::exists(FitfeelBinary())) GTEST_SKIP() << "build the fitfeel target first";
  CliResult r = Fitfeel("validate " + ShellQuote(ShippedScenario("paper-case1-h7js6.yaml")));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("\noutput       about 1.37 MiB (4e+03 trace rows of about 360 B)\n"));

  // An hour at 10 kHz with a recording: about 22 GiB of files.
  const fs::path hour = PaperSceneWith({{"rate: 1000 Hz", "rate: 10 kHz"},
                                        {"duration: 4 s", "duration: 3600 s"},
                                        {"outputs: [trace, summary]",
                                         "outputs: [trace, summary, recording]"}});
  // Located at the duration's value, wherever the shipped file has it.
  std::ifstream text(hour);
  int duration_line = 0;
  for (std::string line; std::getline(text, line);) {
    ++duration_line;
    if (line.rfind("  duration: 3600 s", 0) == 0) break;
  }
  const std::string refused =
      hour.string() + ":" + std::to_string(duration_line) +
      ":13: run.duration: expected a run whose trace.csv and recording.csv "
                      "stay within 4 GiB, or --allow-large to write them anyway, found '3600 s': "
                      "22.1 GiB of output (3.6e+07 trace rows of about 360 B, 3.6e+07 recording "
                      "rows of about 300 B)\n";
  r = Fitfeel("validate " + ShellQuote(hour.string()));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "fitfeel: error: " + refused);
  EXPECT_THAT(r.out, Not(HasSubstr("valid")));
  r = Fitfeel("run " + ShellQuote(hour.string()) + " --out out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "fitfeel: error: " + refused);
  EXPECT_TRUE(fs::is_empty(work_));
  r = Fitfeel("validate --allow-large " + ShellQuote(hour.string()));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("\noutput       about 22.1 GiB (3.6e+07 trace rows of about 360 B, "
                               "3.6e+07 recording rows of about 300 B)\nvalid\n"));

  // The same hour writing only its summary is admitted: the threshold is the files'.
  const fs::path summary = PaperSceneWith({{"rate: 1000 Hz", "rate: 10 kHz"},
                                           {"duration: 4 s", "duration: 3600 s"},
                                           {"outputs: [trace, summary]", "outputs: [summary]"}});
  r = Fitfeel("validate " + ShellQuote(summary.string()));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("\noutput       no trace or recording\n"));
  EXPECT_TRUE(fs::is_empty(work_));
}

// A command that changes a loaded scene's grid or duration re-estimates it as the loader did.
TEST(SceneCostEstimate, IsTheLoadersForTheSceneAsLoadedAndFollowsItsGrid) {
  ::fitfeel::PluginRegistry registry;
  registry.LoadAll();
  ::fitfeel::Scene scene = ::fitfeel::LoadScene(ShippedScenario("fits-20mm-h7g6.yaml"), registry);
  ::fitfeel::SceneCost cost = ::fitfeel::EstimateSceneCost(scene);
  EXPECT_EQ(cost.inner_cells, scene.cost.inner_cells);
  EXPECT_EQ(cost.depth_steps, scene.cost.depth_steps);
  EXPECT_EQ(cost.prepare_bytes, scene.cost.prepare_bytes);
  EXPECT_EQ(cost.prepare_seconds, scene.cost.prepare_seconds);
  EXPECT_EQ(cost.output_bytes, scene.cost.output_bytes);
  EXPECT_FALSE(::fitfeel::LargeCostRefusal(cost));
  scene.model.resolution = {2000, 2000};
  cost = ::fitfeel::EstimateSceneCost(scene);
  EXPECT_EQ(cost.inner_cells, 4'000'000);
  ASSERT_TRUE(::fitfeel::LargeCostRefusal(cost));
  EXPECT_FALSE(::fitfeel::LargeCostRefusal(cost)->output);

  // The default ladder leaves out what the elastic law's worst case puts over 30 s, said, unless
  // --allow-large.
  const std::vector<::fitfeel::Resolution> ladder = ::fitfeel::tradeoff::DefaultLadder();
  std::vector<std::string> left_out;
  const std::vector<::fitfeel::Resolution> admitted =
      ::fitfeel::tradeoff::AdmittedGrids(scene, ladder, false, &left_out);
  ASSERT_EQ(left_out.size(), 1u);
  EXPECT_THAT(left_out[0], HasSubstr("160x1440, over the large-scene thresholds ("));
  EXPECT_THAT(left_out[0], HasSubstr("; --allow-large keeps it)"));
  EXPECT_EQ(admitted.size(), ladder.size() - 1);
  left_out.clear();
  EXPECT_EQ(::fitfeel::tradeoff::AdmittedGrids(scene, ladder, true, &left_out).size(),
            ladder.size());
  EXPECT_TRUE(left_out.empty());
}

}  // namespace
