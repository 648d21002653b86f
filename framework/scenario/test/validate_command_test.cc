// Runs the real `fitfeel validate` binary on bad scenario files: exit code 2, the precise message
// on stderr, no "valid" on stdout, and no file created anywhere in the working folder.
#include <filesystem>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/testing/cli_runner.h"

namespace {

namespace fs = std::filesystem;
using ::fitfeel::test_support::CliOptions;
using ::fitfeel::test_support::CliResult;
using ::fitfeel::test_support::RunFitfeel;
using ::fitfeel::test_support::ShellQuote;
using ::testing::HasSubstr;
using ::testing::Not;

const fs::path kSource = FITFEEL_TEST_SOURCE_DIR;
const fs::path kFitfeel = ::fitfeel::test_support::FitfeelBinary();

// Runs `fitfeel validate <scenario>` inside an empty folder `cwd`.
CliResult Validate(const fs::path& scenario, const fs::path& cwd) {
  return RunFitfeel("validate " + ShellQuote(scenario.string()), CliOptions().In(cwd));
}

fs::path EmptyFolder(const std::string& name) {
  return ::fitfeel::test_support::EmptyFolder("fitfeel_validate_test", name);
}

TEST(ValidateCommandTest, BadScenarioExitsTwoWithTheMessageAndWritesNothing) {
  if (!fs::exists(kFitfeel)) GTEST_SKIP() << "build the fitfeel target first: " << kFitfeel;
  for (const char* name : {"missing_unit", "yaml_syntax", "nonexistent_plugin"}) {
    const fs::path file = kSource / "framework/scenario/test/bad" / (std::string(name) + ".yaml");
    const fs::path cwd = EmptyFolder(name);
    const CliResult result = Validate(file, cwd);
    EXPECT_EQ(result.exit_code, 2) << name << ": " << result.err;
    EXPECT_THAT(result.err, HasSubstr("fitfeel: error: " + file.string() + ":")) << name;
    EXPECT_THAT(result.err, HasSubstr(": expected ")) << name;
    EXPECT_THAT(result.out, Not(HasSubstr("valid"))) << name;
    EXPECT_TRUE(fs::is_empty(cwd)) << name << " left files behind";
  }
  // A syntax error is found before any plugin is needed, so the whole message is known here.
  const fs::path cwd = EmptyFolder("syntax");
  const fs::path file = kSource / "framework/scenario/test/bad/yaml_syntax.yaml";
  EXPECT_EQ(Validate(file, cwd).err, "fitfeel: error: " + file.string() +
                                         ":10:9: expected valid YAML, found end of map flow "
                                         "not found\n");
}

TEST(ValidateCommandTest, MissingFileExitsTwo) {
  if (!fs::exists(kFitfeel)) GTEST_SKIP() << "build the fitfeel target first: " << kFitfeel;
  const fs::path cwd = EmptyFolder("missing");
  const CliResult result = Validate(cwd / "nope.yaml", cwd);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_THAT(result.err, HasSubstr("expected a readable scenario file"));
  EXPECT_TRUE(fs::is_empty(cwd));
}

}  // namespace
