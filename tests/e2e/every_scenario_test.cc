// Every scenario shipped in scenarios/ validates and runs with the real CLI and plugins, and
// writes (for a sequence, for each step) the output contract's files with a constrained stage whose statistics in summary.json
// are those of the ticks in trace.csv (two outputs written by separate code from one run).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "framework/testing/cli_runner.h"

namespace fitfeel {
namespace {

namespace fs = std::filesystem;
using test_support::CliOptions;
using test_support::EmptyFolder;
using test_support::ReadText;
using test_support::RunFitfeel;
using test_support::ShellQuote;

std::vector<std::string> Scenarios() {
  std::vector<std::string> names;
  for (const auto& entry :
       fs::directory_iterator(fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios")) {
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// One run's folder against the output contract: trace.csv's constrained ticks are those
// summary.json reports.
void CheckRunFolder(const fs::path& out) {
  const std::string trace = ReadText(out / "trace.csv");
  EXPECT_EQ(trace.rfind("t_s,stage,depth_mm,fx_N,fy_N,fz_N,tick_us", 0), 0u);
  const nlohmann::json summary = nlohmann::json::parse(ReadText(out / "summary.json"));
  EXPECT_FALSE(summary["scenario"].get<std::string>().empty());
  EXPECT_GT(summary["constrained_ticks"].get<double>(), 0.0) << "never reached the mating stage";
  // The constrained ticks of trace.csv, whose numbers are written to round trip exactly.
  std::istringstream rows(trace);
  std::string line;
  std::getline(rows, line);
  struct Stats {
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();
    double sum = 0.0;
    int count = 0;
    void Add(double v) {
      min = std::min(min, v);
      max = std::max(max, v);
      sum += v;
      ++count;
    }
  } axial, radial;
  int ticks = 0, interference_ticks = 0;
  while (std::getline(rows, line)) {
    ++ticks;
    std::vector<std::string> cells;
    std::istringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    ASSERT_GE(cells.size(), 16u) << line;
    if (cells[1] != "constrained") continue;
    const double fx = std::stod(cells[3]), fy = std::stod(cells[4]), fz = std::stod(cells[5]);
    axial.Add(std::abs(fy));
    radial.Add(std::hypot(fx, fz));
    if (cells[15] == "1") ++interference_ticks;
  }
  EXPECT_EQ(summary["ticks"].get<int>(), ticks);
  EXPECT_EQ(summary["constrained_ticks"].get<int>(), axial.count);
  EXPECT_EQ(summary["interference_ticks"].get<int>(), interference_ticks);
  for (const auto& [key, stats] : {std::pair{"axial_resistance_N", axial},
                                   std::pair{"radial_resistance_N", radial}}) {
    const auto& s = summary[key];
    EXPECT_EQ(s["min"].get<double>(), stats.min) << key;
    EXPECT_EQ(s["max"].get<double>(), stats.max) << key;
    EXPECT_NEAR(s["mean"].get<double>(), stats.sum / stats.count,
                1e-12 * std::max(1.0, std::abs(stats.max)))
        << key;
  }
  EXPECT_EQ(summary["guard_faults"], 0);
}

class EveryScenarioTest : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScenarioTest, ValidatesAndRunsToTheOutputContract) {
  const fs::path file = fs::path(FITFEEL_TEST_SOURCE_DIR) / "scenarios" / (GetParam() + ".yaml");
  const auto validated = RunFitfeel("validate " + ShellQuote(file.string()));
  ASSERT_EQ(validated.exit_code, 0) << validated.out << validated.err;
  EXPECT_NE(validated.out.find("valid"), std::string::npos);

  const fs::path out = EmptyFolder("every-scenario", GetParam()) / "run";
  const auto run =
      RunFitfeel("run " + ShellQuote(file.string()) + " --out " + ShellQuote(out.string()));
  ASSERT_EQ(run.exit_code, 0) << run.out << run.err;
  // A sequence writes each step's run into a folder of its own, listed in its summary.json.
  const nlohmann::json top = nlohmann::json::parse(ReadText(out / "summary.json"));
  if (top.contains("steps")) {
    ASSERT_FALSE(top["steps"].empty());
    for (const auto& step : top["steps"]) {
      SCOPED_TRACE(step["step"].get<std::string>());
      CheckRunFolder(out / step["folder"].get<std::string>());
    }
    return;
  }
  CheckRunFolder(out);
}

INSTANTIATE_TEST_SUITE_P(Shipped, EveryScenarioTest, ::testing::ValuesIn(Scenarios()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = param.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

}  // namespace
}  // namespace fitfeel
