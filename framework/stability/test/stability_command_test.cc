// Runs the real `fitfeel stability` binary on the paper case 1 scene (with the registry's test
// device, found through FITFEEL_PLUGIN_PATH; the cylindrical plugin comes from the build tree).
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
using ::fitfeel::test_support::CliOptions;
using ::fitfeel::test_support::CliResult;
using ::fitfeel::test_support::ReadText;
using ::testing::HasSubstr;

using ::fitfeel::test_support::kBuildTree;
using ::fitfeel::test_support::kSourceTree;
using ::fitfeel::test_support::Lines;
using ::fitfeel::test_support::SplitCells;
const fs::path kStillScene = kSourceTree / "framework/stability/test/case1_still.yaml";

fs::path StabilityFolder(const std::string& name) {
  return ::fitfeel::test_support::EmptyFolder("fitfeel_stability_test", name);
}

// `fitfeel stability <arguments>` (shell text) in `cwd`, with the registry's test device.
CliResult Stability(const std::string& arguments, const fs::path& cwd) {
  return ::fitfeel::test_support::RunFitfeel(
      "stability " + arguments,
      CliOptions().In(cwd).WithPluginPath((kBuildTree / "test-plugins/good").string()));
}

TEST(StabilityCommand, WritesTheMapAndShowsBothMethodsAtTheCaseStiffness) {
  const fs::path dir = StabilityFolder("map");
  const CliResult r = Stability("'" + kStillScene.string() +
                                    "' --rate '500 Hz,1 kHz' --damping '0 N*s/m' --per-decade 4 "
                                    "--horizon '1 s' -o map.csv",
                                dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = Lines(ReadText(dir / "map.csv"));
  // 2 methods x 2 rates x 1 damping x (13 log-spaced + k_p + Lame) stiffnesses.
  ASSERT_EQ(lines.size(), 1u + 2u * 2u * 15u);
  EXPECT_EQ(lines[0],
            "method,rate_Hz,stiffness_N_per_m,damping_Ns_per_m,bound_ok,stable,energy_growth_J,"
            "peak_force_N");
  int case_rows = 0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> c = SplitCells(lines[i]);
    ASSERT_EQ(c.size(), 8u) << lines[i];
    const double k = std::stod(c[2]);
    EXPECT_LE(std::stod(c[7]), 7.9) << lines[i];  // PHANTOM Desktop peak force
    if (c[0] == "coupled") {
      EXPECT_EQ(c[5], "1") << lines[i];
    }
    if (k == 3.665e9 || k == 7.33e9) {
      ++case_rows;
      EXPECT_EQ(c[4], "0");
      EXPECT_EQ(c[5], c[0] == "coupled" ? "1" : "0") << lines[i];
    }
  }
  EXPECT_EQ(case_rows, 8);
  EXPECT_THAT(r.out, HasSubstr("PHANTOM Desktop"));
  EXPECT_THAT(r.out, HasSubstr("3.665e+09 N/m at the device"));
  EXPECT_THAT(r.out, HasSubstr("map.csv"));
}

// Without a scenario the command takes the paper's case 1 from the repository's scenarios/
// (run from the repository's root, as a user would).
TEST(StabilityCommand, DefaultScenarioIsThePaperCase) {
  const fs::path dir = StabilityFolder("default");
  const CliResult r =
      Stability("--rate 1kHz --damping 0Ns/m --per-decade 1 --horizon '0.5 s' -o '" +
                    (dir / "m.csv").string() + "'",
                kSourceTree);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("paper-case1-h7js6"));
  EXPECT_THAT(r.out, HasSubstr("k_p = 3.665e+09 N/m"));
  EXPECT_THAT(ReadText(dir / "m.csv"), HasSubstr("coupled,1000,3665000000,0,0,1,"));
}

// -o FILE.png draws the map itself (no script from the source tree) and writes its data beside it.
TEST(StabilityCommand, DrawsTheMapAsAPictureWithItsData) {
  const fs::path dir = StabilityFolder("picture");
  const CliResult r = Stability("'" + kStillScene.string() +
                                    "' --rate '1 kHz' --damping '0 N*s/m,2 N*s/m' --per-decade 1 "
                                    "--horizon '0.5 s' -o map.png",
                                dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string png = ReadText(dir / "map.png");
  ASSERT_GT(png.size(), 1000u);
  EXPECT_EQ(png.substr(1, 3), "PNG");
  EXPECT_THAT(ReadText(dir / "map.csv"), HasSubstr("coupled,1000,"));
}

TEST(StabilityCommand, DeviceAndForceScaleChangeTheMap) {
  const fs::path dir = StabilityFolder("touch");
  const CliResult r = Stability("'" + kStillScene.string() +
                                    "' --device touch --force-scale 0.01 --rate '1 kHz' "
                                    "--damping 0Ns/m --per-decade 2 --horizon '0.5 s' -o m.csv",
                                dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("Touch"));
  const std::string csv = ReadText(dir / "m.csv");
  EXPECT_THAT(csv, HasSubstr("coupled,1000,36650000,0,0,1,"));
  for (const std::string& line : Lines(csv)) {
    if (line.rfind("method", 0) == 0) continue;
    EXPECT_LE(std::stod(SplitCells(line)[7]), 3.3) << line;  // Touch peak force
  }
}

TEST(StabilityCommand, BadInputExitsTwoAndWritesNothing) {
  const fs::path dir = StabilityFolder("bad");
  const std::string scene = "'" + kStillScene.string() + "'";
  struct Case {
    std::string arguments;
    std::string message;
  };
  const std::vector<Case> cases = {
      {scene + " --device nosuch -o m.csv", "nosuch"},
      {scene + " --rate '1 km' -o m.csv", "--rate"},
      {scene + " --damping 3 -o m.csv", "--damping"},
      {scene + " --stiffness-min '1 N/mm' --stiffness-max '1 N/m' -o m.csv", "stiffness"},
      {scene + " --hand-mass '-1 kg' -o m.csv", "hand-mass"},
      {scene + " --push '5 N' -o m.csv", "--push"},
      {scene + " --push '0 N' -o m.csv", "--push"},
      {scene + " --force-scale 0 -o m.csv", "force-scale"},
      {scene + " -o missing/m.csv", "does not exist"},
      {"'" + (dir / "nosuch.yaml").string() + "' -o m.csv", "nosuch.yaml"},
  };
  for (const Case& c : cases) {
    const CliResult r = Stability(c.arguments, dir);
    EXPECT_EQ(r.exit_code, 2) << c.arguments << "\n" << r.err;
    EXPECT_THAT(r.err, HasSubstr(c.message)) << c.arguments;
    EXPECT_FALSE(fs::exists(dir / "m.csv")) << c.arguments;
  }
  // No temporary file left behind either.
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace
