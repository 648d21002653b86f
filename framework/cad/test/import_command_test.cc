// `fitfeel import` as a user runs it: the paper case from STEP (AP242 with PMI, or AP214 and a
// sidecar) gives the YAML paper case's scene, whose run gives its trace; a reader crash is exit 2.
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/testing/cli_runner.h"

namespace fitfeel::cad {
namespace {

namespace fs = std::filesystem;
using test_support::CliOptions;
using test_support::RunFitfeel;
using test_support::ShellQuote;
using ::testing::HasSubstr;

std::string FixtureWord(const std::string& name) {
  return ShellQuote((fs::path(fitfeel_test_build_dir()) / "cad-fixtures" / name).string());
}
std::string SidecarWord(const std::string& name) {
  return ShellQuote((fs::path(fitfeel_test_source_dir()) / "framework/cad/test" / name).string());
}

// The scenario without its comments and name: what the scene is made of.
std::vector<std::string> Content(const fs::path& file) {
  std::vector<std::string> out;
  for (std::string line : test_support::Lines(test_support::ReadText(file))) {
    const std::size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    if (!line.empty() && line.rfind("scenario:", 0) != 0) out.push_back(line);
  }
  return out;
}

// The trace's numbers, without tick_us (the wall-clock time a tick took, different every run).
std::vector<std::vector<double>> Trace(const fs::path& file) {
  std::vector<std::vector<double>> rows;
  const std::vector<std::string> lines = test_support::Lines(test_support::ReadText(file));
  if (lines.empty()) return rows;
  const std::vector<std::string> header = test_support::SplitCells(lines.front());
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].empty()) continue;
    std::vector<double> row;
    const std::vector<std::string> cells = test_support::SplitCells(lines[i]);
    for (std::size_t j = 0; j < cells.size(); ++j) {
      if (j < header.size() && header[j] == "tick_us") continue;
      row.push_back(std::strtod(cells[j].c_str(), nullptr));
    }
    rows.push_back(row);
  }
  return rows;
}

TEST(ImportCommand, PaperCaseFromStepRunsAsTheYamlPaperCase) {
  const fs::path dir = test_support::EmptyTestFolder("import");
  const test_support::CliResult imported =
      RunFitfeel("import " + FixtureWord("paper-ap242.step") + " --sidecar " +
                     SidecarWord("paper-ap242.sidecar.yaml") + " -o from-ap242.yaml",
                 CliOptions().In(dir));
  ASSERT_EQ(imported.exit_code, 0) << imported.err;
  EXPECT_THAT(imported.out, HasSubstr("pair 1: bushing hole-1 / shaft cylinder-1"));
  const test_support::CliResult from_214 =
      RunFitfeel("import " + FixtureWord("paper-ap214.step") + " --sidecar " +
                     SidecarWord("paper-ap214.sidecar.yaml") + " -o from-ap214.yaml",
                 CliOptions().In(dir));
  ASSERT_EQ(from_214.exit_code, 0) << from_214.err;
  EXPECT_EQ(Content(dir / "from-ap242.yaml"), Content(dir / "from-ap214.yaml"));

  const fs::path yaml = fs::path(fitfeel_test_source_dir()) / "scenarios/paper-case1-h7g6.yaml";
  for (const auto& [scenario, out] :
       {std::pair{(dir / "from-ap242.yaml").string(), "cad"}, std::pair{yaml.string(), "yaml"}}) {
    const test_support::CliResult run =
        RunFitfeel("run " + ShellQuote(scenario) + " --out " + out, CliOptions().In(dir));
    ASSERT_EQ(run.exit_code, 0) << run.err;
  }
  const auto cad = Trace(dir / "cad" / "trace.csv");
  const auto reference = Trace(dir / "yaml" / "trace.csv");
  ASSERT_EQ(cad.size(), reference.size());
  ASSERT_GT(cad.size(), 1000u);
  double worst = 0.0;
  for (std::size_t i = 0; i < cad.size(); ++i) {
    ASSERT_EQ(cad[i].size(), reference[i].size()) << "row " << i;
    for (std::size_t j = 0; j < cad[i].size(); ++j) {
      worst = std::max(worst, std::abs(cad[i][j] - reference[i][j]));
    }
  }
  EXPECT_LE(worst, 1e-9);
}

// The largest difference between two traces' numbers; fails when their shapes differ.
double TraceDifference(const fs::path& a, const fs::path& b) {
  const auto first = Trace(a);
  const auto second = Trace(b);
  EXPECT_EQ(first.size(), second.size());
  EXPECT_GT(first.size(), 1000u);
  double worst = first.size() == second.size() ? 0.0 : 1e300;
  for (std::size_t i = 0; i < std::min(first.size(), second.size()); ++i) {
    EXPECT_EQ(first[i].size(), second[i].size()) << "row " << i;
    for (std::size_t j = 0; j < std::min(first[i].size(), second[i].size()); ++j) {
      worst = std::max(worst, std::abs(first[i][j] - second[i][j]));
    }
  }
  return worst;
}

// A taper pin, a spherical plain bearing and a plate on two pins, drawn as STEP parts with the
// sidecar of what CAD does not carry, run as the shipped scenes of the same parts.
TEST(ImportCommand, ConeSphereAndTwoPinScenesFromStepRunAsTheShippedOnes) {
  const fs::path dir = test_support::EmptyTestFolder("import-surfaces");
  for (const auto& [fixture, sidecar, shipped] :
       {std::tuple{"taper-pin", "taper-pin", "taper-pin"},
        std::tuple{"knuckle-bearing", "knuckle-bearing", "knuckle-bearing"},
        std::tuple{"two-pin", "two-pin", "two-pin-location"}}) {
    SCOPED_TRACE(fixture);
    const std::string name = fixture;
    const test_support::CliResult imported = RunFitfeel(
        "import " + FixtureWord(name + "-ap242.step") + " --sidecar " +
            SidecarWord(std::string(sidecar) + ".sidecar.yaml") + " -o " + name + ".yaml",
        CliOptions().In(dir));
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
    const fs::path yaml =
        fs::path(fitfeel_test_source_dir()) / "scenarios" / (std::string(shipped) + ".yaml");
    for (const auto& [scenario, out] : {std::pair{(dir / (name + ".yaml")).string(), name + "-cad"},
                                        std::pair{yaml.string(), name + "-yaml"}}) {
      const test_support::CliResult run =
          RunFitfeel("run " + ShellQuote(scenario) + " --out " + out, CliOptions().In(dir));
      ASSERT_EQ(run.exit_code, 0) << run.err;
    }
    EXPECT_LE(
        TraceDifference(dir / (name + "-cad") / "trace.csv", dir / (name + "-yaml") / "trace.csv"),
        1e-9);
  }
}

// Without a sidecar the scene takes defaults that run; pairs that form no joint are written one
// at a time.
TEST(ImportCommand, DefaultsRunAndSeveralPairsAreWrittenOneAtATime) {
  const fs::path dir = test_support::EmptyTestFolder("import-defaults");
  for (const std::string name : {"taper-pin", "knuckle-bearing"}) {
    const test_support::CliResult imported =
        RunFitfeel("import " + FixtureWord(name + "-ap242.step") + " -o " + name + ".yaml",
                   CliOptions().In(dir));
    ASSERT_EQ(imported.exit_code, 0) << imported.err;
    const test_support::CliResult run =
        RunFitfeel("run " + name + ".yaml --out " + name, CliOptions().In(dir));
    EXPECT_EQ(run.exit_code, 0) << name << ": " << run.err;
  }
  const std::string pins = "import " + FixtureWord("separate-pins-ap242.step") + " --sidecar " +
                           SidecarWord("separate-pins.sidecar.yaml");
  const test_support::CliResult refused = RunFitfeel(pins + " -o pins.yaml", CliOptions().In(dir));
  EXPECT_NE(refused.exit_code, 0);
  EXPECT_THAT(refused.err, HasSubstr("write one scenario per pair with --pair N"));
  const test_support::CliResult second =
      RunFitfeel(pins + " --pair 2 -o pin-2.yaml", CliOptions().In(dir));
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_THAT(second.out, HasSubstr("scene: one per pair, with --pair N"));
  EXPECT_THAT(test_support::ReadText(dir / "pin-2.yaml"), HasSubstr("  pin-2:\n    role: inner"));
  EXPECT_EQ(RunFitfeel("run pin-2.yaml --out pin-2", CliOptions().In(dir)).exit_code, 0);
}

// A scene whose parts name the paper case's STEP features (the file beside the scene, the
// sidecar elsewhere) runs as the YAML paper case; a missing file or feature is refused where the
// scene names it.
TEST(ImportCommand, AScenesPartsMayNameCadFeatures) {
  const fs::path dir = test_support::EmptyTestFolder("import-cad-parts");
  fs::copy_file(fs::path(fitfeel_test_build_dir()) / "cad-fixtures" / "paper-ap242.step",
                dir / "paper-ap242.step");
  const std::string sidecar =
      (fs::path(fitfeel_test_source_dir()) / "framework/cad/test/paper-ap242.sidecar.yaml")
          .string();
  const auto scene = [&](const std::string& file, const std::string& bore) {
    return "scenario: cad-parts\n"
           "surface: fitfeel.surface.cylindrical\n"
           "parts:\n"
           "  shaft: {role: inner, cad: {file: " +
           file + ", feature: cylinder-1, sidecar: \"" + sidecar +
           "\"}}\n"
           "  bushing:\n"
           "    role: outer\n"
           "    cad: {file: paper-ap242.step, feature: " +
           bore + ", sidecar: \"" + sidecar +
           "\"}\n"
           "moving: shaft\n"
           "model: {law: elastic, friction: 0.15, contact_stiffness: 3665 N/um, resolution: "
           "{rows: 40, columns: 360}, texture: din7190, options: {tilt: free}, depth_step: auto}\n"
           "part_motion: {radial_load: 2 N}\n"
           "device: {plugin: fitfeel.device.simulated, speed: 10 mm/s}\n"
           "run: {rate: 1000 Hz, duration: 4 s, seed: 1, clock: virtual, outputs: [trace, "
           "summary]}\n";
  };
  test_support::WriteText(dir / "cad.yaml", scene("paper-ap242.step", "hole-1"));
  test_support::WriteText(dir / "no-file.yaml", scene("missing.step", "hole-1"));
  test_support::WriteText(dir / "no-feature.yaml", scene("paper-ap242.step", "hole-7"));
  const test_support::CliResult run = RunFitfeel("run cad.yaml --out cad", CliOptions().In(dir));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const fs::path yaml = fs::path(fitfeel_test_source_dir()) / "scenarios/paper-case1-h7g6.yaml";
  ASSERT_EQ(RunFitfeel("run " + ShellQuote(yaml.string()) + " --out yaml", CliOptions().In(dir))
                .exit_code,
            0);
  EXPECT_LE(TraceDifference(dir / "cad" / "trace.csv", dir / "yaml" / "trace.csv"), 1e-9);

  const test_support::CliResult no_file = RunFitfeel("validate no-file.yaml", CliOptions().In(dir));
  EXPECT_EQ(no_file.exit_code, 2);
  EXPECT_THAT(no_file.err, HasSubstr("no-file.yaml:4:36: parts.shaft.cad.file: expected a STEP "
                                     "file (a path from the scenario's folder), found "
                                     "'missing.step', which is no file"));
  const test_support::CliResult no_feature =
      RunFitfeel("validate no-feature.yaml", CliOptions().In(dir));
  EXPECT_EQ(no_feature.exit_code, 2);
  EXPECT_THAT(no_feature.err,
              HasSubstr("no-feature.yaml:7:44: parts.bushing.cad.feature: expected a feature of "
                        "bushing (hole-1, cylinder-1, plane-1, plane-2), found 'hole-7'"));
}

TEST(ImportCommand, AReaderCrashIsAClearErrorWithExitTwo) {
  const std::string command = "env FITFEEL_TEST_CAD_READER=abort " +
                              ShellQuote(test_support::FitfeelBinary().string()) + " import " +
                              FixtureWord("paper-ap242.step") + " 2>&1";
  std::string said;
  FILE* pipe = ::popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) said += buffer;
  const int status = ::pclose(pipe);
  EXPECT_EQ(WEXITSTATUS(status), 2);
  EXPECT_THAT(said, HasSubstr("fitfeel: error: import: '"));
  EXPECT_THAT(said, HasSubstr("crashed the STEP reader (Aborted)"));
}

}  // namespace
}  // namespace fitfeel::cad
