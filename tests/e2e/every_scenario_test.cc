// Every scenario shipped in scenarios/ validates and runs with the real CLI and plugins, and
// writes the output contract's files with a constrained stage (issue 4: "All five scenarios run,
// and fitfeel validate accepts them").
#include <algorithm>
#include <filesystem>
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
  const std::string trace = ReadText(out / "trace.csv");
  EXPECT_EQ(trace.rfind("t_s,stage,depth_mm,fx_N,fy_N,fz_N,tick_us", 0), 0u);
  const nlohmann::json summary = nlohmann::json::parse(ReadText(out / "summary.json"));
  EXPECT_FALSE(summary["scenario"].get<std::string>().empty());
  EXPECT_GT(summary["constrained_ticks"].get<double>(), 0.0) << "never reached the mating stage";
  for (const char* key : {"axial_resistance_N", "radial_resistance_N"}) {
    const auto& s = summary[key];
    // A constant force's mean may round a few ulp past its extremes.
    const double slack = 1e-12 * std::max(1.0, s["max"].get<double>());
    EXPECT_LE(s["min"].get<double>(), s["mean"].get<double>() + slack) << key;
    EXPECT_LE(s["mean"].get<double>(), s["max"].get<double>() + slack) << key;
  }
  EXPECT_EQ(summary["guard_faults"], 0);
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
