// Runs build/bin/fitfeel as a user would and checks the output contract and the physics that
// must hold whatever the model's details: the radial resistance carries the shaft's weight on
// average (momentum balance), and the run is reproducible for a seed.
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
using ::fitfeel::test_support::RunFitfeelInSourceTree;

using ::fitfeel::test_support::kSourceTree;

fs::path FreshDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("fitfeel-e2e-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

std::vector<std::vector<std::string>> ReadCsv(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::string>> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

// Every column but tick_us (a measurement of this machine).
std::vector<std::vector<std::string>> RowPhysics(std::vector<std::vector<std::string>> rows) {
  for (auto& row : rows) row.erase(row.begin() + 6);
  return rows;
}

nlohmann::json ReadJson(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

TEST(RunCommandTest, DefaultScenarioWritesTheContractAndCarriesTheShaftsWeight) {
  const fs::path out = FreshDir("default");
  const CliResult r = RunFitfeelInSourceTree("run --virtual --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("axial resistance"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find((out / "trace.csv").string()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find((out / "summary.json").string()), std::string::npos) << r.out;

  const auto summary = ReadJson(out / "summary.json");
  const auto rows = ReadCsv(out / "trace.csv");
  ASSERT_EQ(rows.size(), summary["ticks"].get<std::size_t>() + 1);
  const std::vector<std::string> contract = {"t_s",  "stage", "depth_mm", "fx_N",
                                             "fy_N", "fz_N",  "tick_us"};
  ASSERT_GE(rows[0].size(), contract.size());
  EXPECT_EQ(std::vector<std::string>(rows[0].begin(), rows[0].begin() + 7), contract);
  EXPECT_EQ(summary["scenario"], "paper-case1-h7js6");
  EXPECT_EQ(summary["deadline_misses"], 0);
  ASSERT_GT(summary["constrained_ticks"].get<int>(), 1000);

  // Momentum balance across the axis: over the constrained ticks, sum (F_z - W) h = m dv_z, and
  // the part's radial velocity is bounded, so the mean radial support equals the weight (2 N in
  // the paper's case study) up to m dv / T. Checked over the second half, after the settling.
  int constrained = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) constrained += rows[i][1] == "constrained";
  double sum_fz = 0.0;
  int n = 0, seen = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i][1] != "constrained" || ++seen < constrained / 2) continue;
    sum_fz += std::stod(rows[i][5]);
    ++n;
  }
  EXPECT_NEAR(sum_fz / n, 2.0, 0.1);
  EXPECT_GT(summary["axial_resistance_N"]["mean"].get<double>(), 0.0);
  fs::remove_all(out);
}

TEST(RunCommandTest, SameSeedSameTraceAnotherSeedAnother) {
  const fs::path a = FreshDir("seed-a"), b = FreshDir("seed-b"), c = FreshDir("seed-c");
  ASSERT_EQ(RunFitfeelInSourceTree("run --virtual --seed 11 --out '" + a.string() + "'").exit_code,
            0);
  ASSERT_EQ(RunFitfeelInSourceTree("run --virtual --seed 11 --out '" + b.string() + "'").exit_code,
            0);
  ASSERT_EQ(RunFitfeelInSourceTree("run --virtual --seed 12 --out '" + c.string() + "'").exit_code,
            0);
  EXPECT_EQ(RowPhysics(ReadCsv(a / "trace.csv")), RowPhysics(ReadCsv(b / "trace.csv")));
  EXPECT_NE(RowPhysics(ReadCsv(a / "trace.csv")), RowPhysics(ReadCsv(c / "trace.csv")));
  EXPECT_EQ(ReadJson(a / "summary.json")["seed"], 11);
  for (const auto& d : {a, b, c}) fs::remove_all(d);
}

TEST(RunCommandTest, ABadScenarioExitsTwoAndCreatesNothing) {
  const fs::path dir = FreshDir("bad");
  fs::create_directories(dir);
  const fs::path scene = dir / "bad.yaml";
  {
    std::ifstream in(kSourceTree / "scenarios" / "paper-case1-h7js6.yaml");
    std::stringstream text;
    text << in.rdbuf();
    std::string yaml = text.str();
    // An unknown key at the top level.
    yaml += "\nspeeed: 10 mm/s\n";
    std::ofstream(scene) << yaml;
  }
  const fs::path out = dir / "out";
  const CliResult r =
      RunFitfeelInSourceTree("run '" + scene.string() + "' --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("bad.yaml:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("speeed"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out));

  const CliResult missing = RunFitfeelInSourceTree("run '" + (dir / "nowhere.yaml").string() + "'");
  EXPECT_EQ(missing.exit_code, 2) << missing.out;
  fs::remove_all(dir);
}

}  // namespace
