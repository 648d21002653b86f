// Runs the real `fitfeel tradeoff` binary on the paper case 1 scene with a small ladder, two seeds
// and a short duration, so that it finishes in seconds.
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/testing/cli_runner.h"
#include "framework/testing/source_tree.h"

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

using ::fitfeel::test_support::kBuildTree;
using ::fitfeel::test_support::kSourceTree;
using ::fitfeel::test_support::ReadText;
using ::fitfeel::test_support::SplitCells;
const fs::path kTradeoffScene = kSourceTree / "scenarios/paper-case1-h7js6.yaml";

struct Result {
  int exit_code = -1;
  std::string out;
  std::string err;
};

fs::path TradeoffFolder(const std::string& name) {
  return ::fitfeel::test_support::EmptyFolder("fitfeel_tradeoff_test", name);
}

// The plugins come from the build tree (the registry's default search path for a build).
Result Tradeoff(const std::string& arguments, const fs::path& cwd) {
  const fs::path out = cwd / ".stdout", err = cwd / ".stderr";
  const std::string command = "cd '" + cwd.string() + "' && '" +
                              (kBuildTree / "bin/fitfeel").string() + "' tradeoff " + arguments +
                              " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  Result result;
  if (WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  result.out = ReadText(out);
  result.err = ReadText(err);
  fs::remove(out);
  fs::remove(err);
  return result;
}

bool Empty(const fs::path& dir) { return fs::is_empty(dir); }

TEST(TradeoffCommand, WritesCsvAndChartsForASmallLadder) {
  const fs::path dir = TradeoffFolder("ladder");
  const Result r = Tradeoff("'" + kTradeoffScene.string() +
                                "' -o small --resolutions 20x90,8x36,10x72 --seeds 2 "
                                "--duration '1.5 s'",
                            dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("reference"));
  const std::vector<std::string> lines = SplitCells(ReadText(dir / "small.csv"), '\n');
  ASSERT_EQ(lines.size(), 4u);
  const std::vector<std::string> header = SplitCells(lines[0], ',');
  const std::vector<std::string> expected = {
      "grid",        "inner_rows",     "inner_columns", "outer_rows",    "outer_columns",
      "inner_cells", "outer_cells",    "seeds",         "prepare_s",     "tick_p50_us",
      "tick_p99_us", "mean_axial_N",   "sd_axial_N",    "se_axial_N",    "bias_N",
      "bias_se_N",   "rms_error_N",    "max_error_N",   "rms_error_rel", "max_error_rel",
      "noise_rms_N", "compared_ticks", "reference"};
  EXPECT_EQ(header, expected);
  long previous_cells = 0;
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const std::vector<std::string> cells = SplitCells(lines[k], ',');
    ASSERT_EQ(cells.size(), header.size()) << lines[k];
    const long inner_cells = std::stol(cells[5]);
    EXPECT_EQ(inner_cells, std::stol(cells[1]) * std::stol(cells[2]));
    EXPECT_GT(inner_cells, previous_cells) << "rows must go coarse to fine";
    previous_cells = inner_cells;
    EXPECT_EQ(cells[7], "2");
    EXPECT_GT(std::stod(cells[9]), 0.0);   // tick p50
    EXPECT_GT(std::stod(cells[11]), 0.0);  // mean axial resistance
    EXPECT_GE(std::stod(cells[12]), 0.0);  // seed spread
    EXPECT_GT(std::stol(cells[21]), 0);    // compared ticks
    EXPECT_EQ(cells[22], k + 1 == lines.size() ? "yes" : "no");
  }
  EXPECT_EQ(SplitCells(lines[1], ',')[0], "8x36");
  EXPECT_EQ(SplitCells(lines[3], ',')[0], "20x90");
  EXPECT_EQ(std::stod(SplitCells(lines[3], ',')[16]), 0.0);  // the reference against itself
  EXPECT_EQ(ReadText(dir / "small.png").rfind("\x89PNG", 0), 0u);
  EXPECT_THAT(ReadText(dir / "small.svg"), HasSubstr("<svg"));
}

// Two grids with one seed: a single compared grid on the error panel, no paired noise.
TEST(TradeoffCommand, ChartsTwoGridsWithOneSeed) {
  const fs::path dir = TradeoffFolder("pair");
  const Result r = Tradeoff("'" + kTradeoffScene.string() +
                                "' -o pair --resolutions 8x36,10x72 --seeds 1 --duration '1 s' "
                                "--cost p99",
                            dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = SplitCells(ReadText(dir / "pair.csv"), '\n');
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(SplitCells(lines[1], ',')[20], "0");  // one seed: no sampling noise estimate
  EXPECT_EQ(ReadText(dir / "pair.png").rfind("\x89PNG", 0), 0u);
}

TEST(TradeoffCommand, BadInputExitsTwoAndWritesNothing) {
  const fs::path dir = TradeoffFolder("bad");
  const std::string scene = "'" + kTradeoffScene.string() + "'";
  Result r = Tradeoff(scene + " -o x --resolutions 8x35", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("even"));
  r = Tradeoff(scene + " -o x --resolutions 8x36,garbage", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("'garbage'"));
  r = Tradeoff(scene + " -o x --seeds 0", dir);
  EXPECT_EQ(r.exit_code, 2);
  r = Tradeoff(scene + " -o x --duration '3 kg'", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("--duration"));
  r = Tradeoff(scene + " -o no-such-folder/x --resolutions 8x36", dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_THAT(r.err, HasSubstr("does not exist"));
  r = Tradeoff("no-such-scene.yaml -o x", dir);
  EXPECT_EQ(r.exit_code, 2);
  r = Tradeoff("", dir);  // the scenario is required
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(Empty(dir));
}

}  // namespace
